"""Every float option of every command refuses NaN and infinity.

click's FLOAT (and FloatRange: NaN compares false with both bounds) accepts `nan` and `inf`,
and then `--timeout nan` never times out and `--distance nan` prints "nan" in a banner. The
command tree gives each float parameter a finite type (`Finite`) as it builds a command
(`ttctl.commands.lazy`), so a new option is covered without anyone remembering to.
"""

from __future__ import annotations

import math
from typing import Any

import click


def _check(self: click.ParamType, out: Any, value: Any, param: click.Parameter | None,
           ctx: click.Context | None) -> Any:
    if isinstance(out, float) and not math.isfinite(out):
        self.fail(f"{value!r} is not a finite number (NaN and infinity are refused).", param, ctx)
    return out


class FiniteFloat(click.types.FloatParamType):
    """click's FLOAT, refusing NaN and +-inf."""

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        return _check(self, super().convert(value, param, ctx), value, param, ctx)


class FiniteFloatRange(click.FloatRange):
    """click's FloatRange (its help shows the range as before), refusing NaN and +-inf."""

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        return _check(self, super().convert(value, param, ctx), value, param, ctx)


Finite = (FiniteFloat, FiniteFloatRange)


def finite_floats(cmd: click.Command) -> click.Command:
    """`cmd` with each float parameter's type made finite (in place; returned)."""
    for p in cmd.params:
        t = p.type
        if isinstance(t, Finite):
            continue
        if isinstance(t, click.FloatRange):
            new: click.ParamType = FiniteFloatRange.__new__(FiniteFloatRange)
        elif isinstance(t, click.types.FloatParamType):
            new = FiniteFloat.__new__(FiniteFloat)
        else:
            continue
        new.__dict__.update(t.__dict__)
        p.type = new
    return cmd


__all__ = ["Finite", "FiniteFloat", "FiniteFloatRange", "finite_floats"]
