"""Handouts and worksheets: the document model, what they say, and the PDF and LaTeX writers.

  document          a handout as frozen blocks (headings, paragraphs, tables, diagrams, strips, questions)
  build             `build`: a handout's sections assembled from the modules below, its title and headings
  words             numbers and names as the sentences write them (17/12 L, +0.6 c, B₁, S′)
  reading           `Reading`: a history read once for the text (instants, collisions, turns, velocities)
  narrative         the set-up, the diagram's caption and the explanation of what it shows
  strips            the rod at successive instants: which instants, and their caption
  worksheet         which questions a worksheet asks; `worksheet_frames` and `worksheet_rod` build them
  forces            a rod driven by forces: its section, Sears's own paradox (`forces_reading` reads the history,
                    `worksheet_forces` asks the questions)
  pdf               the blocks measured and set on pages with matplotlib's PDF backend
  pdf_text          the type, words wrapped into lines, and the pages they are set on
  tex               the blocks as a folder of LaTeX, figures and pgfplots data
  readme_pictures   the README's picture of a handout's first page

Imports `render`, `tables`, `io`, `physics` and the base modules, never the command line.
"""
