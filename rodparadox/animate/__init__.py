"""Animations: the timeline (pure), the two scenes (now and boost, matplotlib) and the encoders (GIF, MP4, PNG).

  timeline  what each panel shows at each instant: the now of each frame, the strips, the boost
  scenes    the frames drawn: now mode over `plot`'s diagram, boost mode over fixed axes
  encoders  images -> GIF, MP4 (ffmpeg) or numbered PNG stills

Imports `render`, `io`, `physics` and the base modules, never the command line.
"""
