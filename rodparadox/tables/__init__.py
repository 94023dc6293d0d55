"""The events and the ledger as tables, and their formats (Markdown, LaTeX). Pure text, no drawing.

  table    a table as plain text cells (`Table` of `Cell`s), what every table here is built as
  build    the events, ledger and hidden tables (`Table` of `Cell`s), built once from a history
  formats  a table as a GitHub pipe table or a booktabs/siunitx LaTeX fragment

Imports `physics` and the base modules (numbers, tolerances).
"""
