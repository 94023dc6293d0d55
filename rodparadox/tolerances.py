"""Named tolerances: where two floats count as one, and why. Imports nothing.

Every "equal up to rounding" in the library names one of these, so how close
is close is decided, and explained, in one place. Lengths and times are in
units of L (or relative to L plus the size of the coordinates compared),
rapidities and velocities are plain numbers, layout is in points. Two
names with one value are kept apart only where they mean different things;
each comment says what the value stands for.
"""

from __future__ import annotations

# --- the engine: events and rapidities, computed in S -------------------------------------------------------------

#: two events closer than this (units of L) are one: the rounding of a boost or a displacement, not a segment
SAME_EVENT = 1e-12
#: impacts at the two ends closer than this on the rod's own time axis (units of L) are one simultaneous impact
#: (rule 5): wider than SAME_EVENT, as the two times come from two particles' separate histories
SIMULTANEITY_TOLERANCE = 1e-10
#: an impact within this (in rapidity) of a turn's last line completes the turn: Fig. 2's A1 and B2 lie exactly on it
TURN_LINE_ROUNDING = 1e-12
#: how far rounding moves a difference of terms, relative to the terms: a thousand ulps of double precision
DIFFERENCE_ROUNDING = 1e3 * 2.2e-16
#: a timed particle strikes where it was aimed if within this, relative to L and the target's coordinates: the
#: engine places events to about 1e-9 relative at its bounds (docs/scenarios.md, "Scenario files")
TIMING_MATCH = 1e-9
#: two rapidities closer than this are one velocity (a handout's reading of a history): the engine ends a turn
#: within TURN_LINE_ROUNDING of its line, and a boost shifts a rapidity by a rounding of about 1e-15 of it
SAME_RAPIDITY = 1e-9

# --- instants of a frame ------------------------------------------------------------------------------------------

#: two impacts closer than this in a frame's time, relative to L plus the largest |t|, are at one instant of it:
#: boosting puts an ulp or two between impacts on one line of the frame, and the engine places events to about
#: 1e-9 relative at its bounds (docs/scenarios.md, "Scenario files"), so impacts meant to be simultaneous may differ by that.
#: A block of stills (`render.strip`) takes an impact as at a still's instant within ONE_INSTANT * L: the stills'
#: times are multiples of L written as floats (17/12 as 1.4166666666666667), rounded far below what a reader sees
ONE_INSTANT = 1e-9
#: one event's time, computed twice (the event boosted, and a world-line through it boosted), agrees to this,
#: relative to L + |t|: a few ulps. The ledger needs this, not ONE_INSTANT: it takes the (E, p) between two
#: impacts, which may be far closer than 1e-9 relative (fig1 at v = 1e-6: 1e-6 L apart at t' = 5e5 L in S')
SAME_INSTANT = 1e-12
#: two impacts share one drawn line of simultaneity when its intercepts agree to this fraction (rounding of a boost)
SAME_LINE = 1e-9
#: a clock ticks at a multiple of its step when the proper time is within this fraction of a step of it
PROPER_TIME_TICK = 1e-12

# --- drawing --------------------------------------------------------------------------------------------------------

#: a sampled polyline stays this close to the true curve (units of L): finer than a printed line's width
SAMPLING_TOLERANCE = 1e-4
#: a step computed from data is taken as a nice number (1, 2, 2.5, 5 times a power of ten), a tick as on a
#: multiple of its step, and a colour bar's tick as 0 (relative to the bar's half-range: S' of fig2 puts its centre
#: at 0.6 - 0.6 = 1.1e-16), within this relative rounding
STEP_ROUNDING = 1e-9
#: a panel's rod velocity below this is written "at rest": a boost leaves a few ulps of a velocity 0
AT_REST = 5e-13
#: a drawing, or a handout's block of text, may need this much more room (points) than its target (the rest of a
#: page) has and still fit: the rounding of laying out
FIT_SLACK = 1e-6

# --- numbers as text --------------------------------------------------------------------------------------------

#: a printed number below this fraction of its table's scale (the largest coordinate; a frame's kinetic energy
#: and momentum for a difference of totals) is rounding, printed 0: double precision carries 16 digits, and the
#: engine's events are exact to about 1e-9 relative at its bounds (docs/scenarios.md, "Scenario files")
PRINTED_ZERO = 1e-12
#: a fraction stands for a float within this relative distance (the engine's rounding is about 1e-15 relative)
FRACTION_MATCH = 1e-12
#: ... and only where a number that is no fraction would match one that well with at most this chance: with
#: FRACTION_MATCH relative, numbers up to about 1e4 keep twelfths, but 909999955/91 for a t near 1e7 is refused
FRACTION_CHANCE = 1e-6
