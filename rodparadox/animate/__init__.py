"""Animations: the timeline (pure), the two scenes (now and boost, matplotlib) and the encoders (GIF, MP4, PNG).

  timeline     what each panel shows at each instant: the now of each frame, the strips, the boost
  scenes       `images_of`: the animation's images, drawn by one of the two scenes
  now_scene    now mode over `plot`'s diagram: each frame's now sweeping up, a band of strips below
  boost_scene  boost mode over fixed axes: the frame runs smoothly from one velocity to another
  images       what both scenes share: blitting their images on one canvas
  encoders     images -> GIF, MP4 (ffmpeg) or numbered PNG stills

An image is one instant of the animation; a frame is always a Lorentz frame. Imports `render`, `io`,
`physics` and the base modules, never the command line.
"""
