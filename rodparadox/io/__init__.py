"""Input and output: YAML scenarios in, JSON/CSV/text out, atomic writes. No drawing.

  scenario       YAML -> `physics.model.Scenario` (the only module that knows YAML)
  export         world-lines and impacts as JSON, CSV and the events text table
  ledger_report  the ledger as text, JSON and CSV
  output         deterministic, atomic writes of files and folders

Imports `physics` and the base modules.
"""
