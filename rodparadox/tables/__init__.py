"""The events and the ledger as tables, and their formats (Markdown, LaTeX). Pure text, no drawing.

  build    the events, ledger and hidden tables (`Table` of `Cell`s), built once from a history
  formats  a table as a GitHub pipe table or a booktabs/siunitx LaTeX fragment

Imports `physics` and the base modules (numbers, tolerances); for now also the `Table` and `Cell` of
`handout.document`, which belong here.
"""
