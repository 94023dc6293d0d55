"""Handouts and worksheets: the document model, what they say, and the PDF and LaTeX writers.

  document  a handout as frozen blocks (headings, paragraphs, tables, diagrams, strips, questions)
  build     what a handout and a worksheet say, generated from the history
  pdf       the blocks set on pages with matplotlib's PDF backend
  tex       the blocks as a folder of LaTeX, figures and pgfplots data

Imports `render`, `tables`, `io`, `physics` and the base modules, never the command line.
"""
