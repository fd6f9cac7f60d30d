"""The dialect the model benchmarks run on: ttctl's shipped ttapi. They measure ttctl's own
protocol (file transfer, commands), whose messages are the same in every dialect that includes
ttapi.xml; live benchmarks (`--to`) speak the user's --dialect instead."""

from __future__ import annotations

from functools import lru_cache

from ..wire.bindings import Bindings


@lru_cache(maxsize=1)
def bindings() -> Bindings:
    import ttapi

    return Bindings(ttapi)


__all__ = ["bindings"]
