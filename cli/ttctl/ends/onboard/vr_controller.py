"""The VR controllers' buttons, built into the onboard end: TT_VR_CONTROLLER from the tablet
(`ttctl hmd dump --to`) applied in order, each button change confirmed.

The tablet resends a button change until it is confirmed (ttctl.hmd.stream), one in flight per
controller, and holds the controller's axis-only messages meanwhile. So here a message whose
buttons differ from the last ones applied is the next change: applied, logged, and confirmed
with NAMED_VALUE_INT name "vrbtn<index>", value = its packet_num (as int32). A copy of the last
change (same packet_num and time: the confirmation was lost) is confirmed again; axis-only
messages (same buttons) update the axes and are not confirmed.

The state is in ctx.shared["vr_controllers"][index]: {"buttons": bits, "trigger", "pad_x",
"pad_y", "packet_num", "changes"} for other plugins.
"""

from __future__ import annotations

from typing import Any

from ...hmd.stream import BUTTON_BITS, ack_name
from ..plugins import Context, Plugin, handles


def _held(bits: int) -> str:
    names = [name for name, bit in BUTTON_BITS.items() if bits & int(bit)]
    return ", ".join(names) if names else "none"


class VrControllerPlugin(Plugin):
    def __init__(self) -> None:
        self.changes = 0
        self._last: dict[int, tuple[int, int, int]] = {}  # index -> (bits, packet_num, time_usec) of the last change

    @handles("TT_VR_CONTROLLER")
    def on_controller(self, msg: Any, ctx: Context) -> None:
        index, bits, key = int(msg.index), int(msg.buttons), (int(msg.packet_num), int(msg.time_usec))
        last = self._last.get(index)
        state = ctx.shared.setdefault("vr_controllers", {}).setdefault(index, {"buttons": 0, "changes": 0})
        state.update(trigger=float(msg.trigger), pad_x=float(msg.pad_x), pad_y=float(msg.pad_y))
        if last is not None and (last[1], last[2]) == key:
            self._confirm(ctx, index, key[0])  # a copy: our confirmation was lost
            return
        if bits == (last[0] if last is not None else 0):
            return  # axes only
        self._last[index] = (bits, *key)
        self.changes += 1
        state.update(buttons=bits, packet_num=key[0], changes=int(state["changes"]) + 1)
        ctx.log(f"vr controller {index}: buttons {_held(bits)} (packet {key[0]})")
        self._confirm(ctx, index, key[0])

    def _confirm(self, ctx: Context, index: int, packet_num: int) -> None:
        b = ctx.dialect
        value = packet_num - (1 << 32) if packet_num >= 1 << 31 else packet_num
        ctx.send(b.NamedValueInt(time_boot_ms=0, name=ack_name(index), value=value), urgent=True)


__all__ = ["VrControllerPlugin"]
