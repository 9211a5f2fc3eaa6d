"""The paper's scripting style (§4.5) over the blending engine.

A script drives characters through an animation service::

    anim = AnimationService.from_runtime(thespis.build_runtime(scenario, folder))
    anim.activate_action_body("Creon", "creon_wrk")
    anim.wait_until_action_finished_body("Creon", "creon_wrk", -4.0)   # 4 s before its end
    anim.activate_action_body("Creon", "creon_idle")
    anim.cut_off_action_body("Antigone", "antigone_idle", 3.0)          # fade out over 3 s

Each character has one live body schedule and a library of named actions (a blendable and its
blending parameters). Activating an action adds it to the schedule at the clock's current time;
waiting advances a ManualClock at once (batch work, tests) or sleeps on a RealTimeClock (live
preview). This module holds no animation logic of its own: it only calls the schedule.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Dict, Optional, Union

from . import _thespis as _t


class ManualClock:
    """Simulated time in seconds: waiting jumps to the awaited time at once."""

    def __init__(self, start: float = 0.0):
        self._now = float(start)

    def now(self) -> float:
        return self._now

    def advance(self, seconds: float) -> float:
        if seconds < 0:
            raise ValueError(f"A clock cannot go back in time (advance by {seconds} s).")
        self._now += seconds
        return self._now

    def wait_until(self, t: float) -> None:
        self._now = max(self._now, float(t))


class RealTimeClock:
    """Wall-clock seconds since the clock was made; waiting sleeps."""

    def __init__(self):
        self._origin = time.monotonic()

    def now(self) -> float:
        return time.monotonic() - self._origin

    def wait_until(self, t: float) -> None:
        while True:
            left = t - self.now()
            if left <= 0:
                return
            time.sleep(min(left, 0.05))


@dataclass
class _ActionTemplate:
    source: _t.Blendable
    params: _t.BlendingParams
    render_outside_domain: bool = False


@dataclass
class _Character:
    schedule: _t.BlendingSchedule
    actions: Dict[str, _ActionTemplate] = field(default_factory=dict)
    active: Dict[str, int] = field(default_factory=dict)  # action name → id of its latest activation


Clock = Union[ManualClock, RealTimeClock]


class AnimationService:
    """Per character a live body schedule and named actions, driven at a clock's time."""

    def __init__(self, clock: Optional[Clock] = None):
        self.clock: Clock = clock if clock is not None else ManualClock()
        self._characters: Dict[str, _Character] = {}

    @classmethod
    def from_runtime(cls, runtime: _t.ScenarioRuntime, clock: Optional[Clock] = None) -> "AnimationService":
        """A service with every character of a built scenario. Each clip is an action of the same
        name (constant weight); each body action of the scenario is an action of its own name with
        its modifiers and blending parameters (these win over a clip of the same name)."""
        service = cls(clock)
        for character in runtime.characters:
            service.add_character(character.name, character.skeleton)
            body_layout = character.skeleton.frame_layout
            for clip_name, clip in character.clips.items():
                if clip.layout == body_layout:  # face clips (MPEG-4 FAPs) are not body actions
                    service.define_action_body(character.name, clip_name, clip)
            for layer, ids in zip(character.layers, character.action_ids):
                if layer.layout != body_layout:
                    continue  # a face layer: not a body action
                for action_id in ids:
                    action = layer.action(action_id)
                    if action is not None and action.name:
                        service.define_action_body(character.name, action.name, action.source, action.params,
                                                   action.render_outside_domain)
        return service

    def add_character(self, name: str, skeleton: _t.Skeleton) -> _t.BlendingSchedule:
        """Adds a character with an empty body schedule on `skeleton`; returns the schedule."""
        if name in self._characters:
            raise ValueError(f"There is already a character called '{name}'.")
        schedule = _t.BlendingSchedule(skeleton)
        self._characters[name] = _Character(schedule)
        return schedule

    def define_action_body(self, character: str, action: str, source: _t.Blendable,
                           params: Optional[_t.BlendingParams] = None, render_outside_domain: bool = False) -> None:
        """Names an action the character can play: `source` blended with `params`."""
        self._character(character).actions[action] = _ActionTemplate(
            source, params if params is not None else _t.BlendingParams(), render_outside_domain)

    def characters(self):
        return list(self._characters)

    def actions_body(self, character: str):
        return sorted(self._character(character).actions)

    def body_schedule(self, character: str) -> _t.BlendingSchedule:
        return self._character(character).schedule

    def activate_action_body(self, character: str, action: str, weight: Optional[_t.Curve] = None) -> int:
        """Starts the named action now (optionally with another weight curve); returns its id."""
        c = self._character(character)
        template = c.actions.get(action)
        if template is None:
            known = ", ".join(sorted(c.actions)) or "none"
            raise KeyError(f"Character '{character}' has no action '{action}' (it has: {known}).")
        now = self.clock.now()
        c.schedule.remove_finished_actions(now)
        params = template.params
        if weight is not None:
            params = _t.BlendingParams(weight, params.scale, params.mask, params.mode, params.additive_reference)
        action_id = c.schedule.add_action(
            _t.BlendingAction(template.source, params, now, action, template.render_outside_domain))
        c.active[action] = action_id
        return action_id

    def cut_off_action_body(self, character: str, action: str, fade: float = 0.5) -> bool:
        """Fades the latest activation of the action out over `fade` seconds from now.
        False when it is not playing."""
        c = self._character(character)
        action_id = c.active.get(action)
        if action_id is None:
            return False
        return c.schedule.cut_off_action(action_id, self.clock.now(), fade)

    def is_action_finished_body(self, character: str, action: str) -> bool:
        c = self._character(character)
        action_id = c.active.get(action)
        return action_id is None or c.schedule.is_finished(action_id, self.clock.now())

    def action_end_body(self, character: str, action: str) -> Optional[float]:
        """When the latest activation ends (inf when open-ended), or None when it is not playing."""
        c = self._character(character)
        action_id = c.active.get(action)
        if action_id is None:
            return None
        end = c.schedule.end_time(action_id)
        return None if math.isnan(end) else end

    def wait_until_action_finished_body(self, character: str, action: str, offset: float = 0.0) -> float:
        """Waits until `offset` seconds after the action's end (a negative offset: before it), as
        the paper's waitUntilActionFinished_body(Creon, "creon_wrk", -4.0). Returns the clock's time."""
        end = self.action_end_body(character, action)
        if end is None:
            return self.clock.now()
        if math.isinf(end):
            raise ValueError(f"Action '{action}' of '{character}' never ends by itself; cut it off first.")
        target = end + offset
        if offset >= 0:
            # An action still plays its last frame at exactly its end time; it is finished
            # just after it, so waiting "until finished" waits for the next representable time.
            target = math.nextafter(target, math.inf)
        self.clock.wait_until(target)
        return self.clock.now()

    def evaluate_body(self, character: str, t: Optional[float] = None):
        """The character's body frame at time t (default: now) as a float32 array."""
        return self._character(character).schedule.evaluate(self.clock.now() if t is None else t)

    def _character(self, name: str) -> _Character:
        try:
            return self._characters[name]
        except KeyError:
            known = ", ".join(sorted(self._characters)) or "none"
            raise KeyError(f"There is no character '{name}' (characters: {known}).") from None
