"""A worksheet's questions: which five to eight are asked of a scenario, in what order (`questions`). Pure.

The questions themselves, with their worked answers, are built in
`worksheet_frames` (reading the panels, a Lorentz transformation, velocity
addition, another speed) and `worksheet_rod` (what the rod does, where the
scenario shows it).
"""

from __future__ import annotations

from typing import Sequence

from rodparadox.handout.document import Question
from rodparadox.handout.reading import Reading
from rodparadox.handout.worksheet_frames import (Asked, frame_pair, lorentz_pair, question_lorentz,
                                                 question_other_speed, question_read, question_velocity)
from rodparadox.handout.worksheet_rod import (question_at_rest, question_hidden, question_momentum, question_single,
                                              question_stopped_turn, question_together, question_zigzag)
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame


def questions(history: RodHistory, frames: Sequence[Frame], compare_v: float | None = None,
              chosen: Sequence[int] | None = None) -> tuple[Question, ...]:
    """Five to eight questions on the scenario, numbered from 1, each with a worked answer computed by the tool:
    read an event off the panels; a Lorentz transformation; velocity addition; the hidden momentum on a slice;
    the questions that fit the scenario (a stopped turn, a rod at rest in a moving frame, a single particle, unequal
    masses, impacts taken together, a zig-zag); and the same scenario at another speed."""
    r = Reading(history, tuple(frames))
    a, b = frame_pair(r)
    pair = lorentz_pair(r, a, b)
    asked: list[Asked] = [question_read(r, a, b, pair), question_lorentz(r, a, b, pair), question_velocity(r, a, b)]
    fitting = [question_hidden(r, a, b), question_stopped_turn(r), question_at_rest(r), question_single(r),
               question_momentum(r, next((c for c in r.collisions if len(c) > 1), None))
               if len({p.mass for p in history.scenario.particles}) > 1 else None,
               question_together(r, b), question_zigzag(r)]
    asked += [q for q in fitting if q is not None]
    other = question_other_speed(r, a, b, compare_v)
    if other is not None:
        asked = asked[:7] + [other]
    if len(asked) < 5:  # a scenario with little to ask about: momentum is conserved at each collision
        asked += [question_momentum(r, c) for c in r.collisions][:5 - len(asked)]
    asked = asked[:8]
    if chosen is not None:  # the teacher's choice (--questions 1,3,5), renumbered from 1 in worksheet and key alike
        asked = [asked[k - 1] for k in chosen if 1 <= k <= len(asked)]
    return tuple(Question(k + 1, q.text, q.answer, q.asks) for k, q in enumerate(asked))
