"""A table as plain text cells: `Table` of `Cell`s, what the events, ledger and hidden tables are built as. Pure.

`tables.build` fills them from a history, `tables.formats` writes them as Markdown
or LaTeX, and a handout (`handout.document`) prints them. Numbers are cells of text
as they should be printed; a cell marked `blank` is one a worksheet leaves empty
(ruled) for the student to fill in, and the answer key prints the same table with
every cell filled.
"""

from __future__ import annotations

from dataclasses import dataclass

#: what a column holds: text flush left, text flush right, or numbers aligned at the decimal point
ALIGNS = ("l", "r", "n")


@dataclass(frozen=True)
class Cell:
    """A table cell: its text, and whether a worksheet leaves it blank for the student."""

    text: str
    blank: bool = False


@dataclass(frozen=True)
class Table:
    """A table: `name` is stable and file-safe (`events_rest`, `ledger_moving`), used for the LaTeX fragment's
    file name; `align` has one letter of ALIGNS per column; `notes` are lines printed under the table."""

    name: str
    caption: str
    header: tuple[str, ...]
    rows: tuple[tuple[Cell, ...], ...]
    align: str
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if len(self.align) != len(self.header) or any(a not in ALIGNS for a in self.align):
            raise ValueError(f"table {self.name}: align {self.align!r} must have one of {ALIGNS} per column")
        for row in self.rows:
            if len(row) != len(self.header):
                raise ValueError(f"table {self.name}: a row has {len(row)} cells for {len(self.header)} columns")

    @property
    def has_blanks(self) -> bool:
        return any(c.blank for row in self.rows for c in row)

    def filled(self) -> "Table":
        """The same table with every cell filled: the answer key's copy of a worksheet's table."""
        rows = tuple(tuple(Cell(c.text) for c in row) for row in self.rows)
        return Table(self.name, self.caption, self.header, rows, self.align, self.notes)
