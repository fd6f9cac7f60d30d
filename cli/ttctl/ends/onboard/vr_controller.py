"""The VR controllers' buttons, built into the onboard end: TT_VR_CONTROLLER from the tablet
(`ttctl hmd dump --to`) applied in order, each message confirmed.

The tablet resends a button change until it is confirmed (ttctl.hmd.stream), one in flight per
controller, and holds the controller's axis-only messages meanwhile, so what arrives here is in
order. Every TT_VR_CONTROLLER is confirmed with NAMED_VALUE_INT name "vrbtn<index>", value = its
packet_num (as int32): a copy whose confirmation was lost is confirmed again, and nothing a
restart of either end leaves behind can leave a change unconfirmed forever (on the M100 link a
few confirmations a second, 26 bytes each, on the 6.7 KB/s downlink). A message whose buttons
differ from the last ones applied (none, before the first) is a change: applied and logged.

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
        self._last: dict[int, int] = {}  # index -> the buttons last applied

    @handles("TT_VR_CONTROLLER")
    def on_controller(self, msg: Any, ctx: Context) -> None:
        index, bits, packet = int(msg.index), int(msg.buttons), int(msg.packet_num)
        state = ctx.shared.setdefault("vr_controllers", {}).setdefault(index, {"buttons": 0, "changes": 0})
        state.update(trigger=float(msg.trigger), pad_x=float(msg.pad_x), pad_y=float(msg.pad_y))
        if bits != self._last.get(index, 0):  # a change (nothing is held before the first)
            self._last[index] = bits
            self.changes += 1
            state.update(buttons=bits, packet_num=packet, changes=int(state["changes"]) + 1)
            ctx.log(f"vr controller {index}: buttons {_held(bits)} (packet {packet})")
        self._confirm(ctx, index, packet)

    def _confirm(self, ctx: Context, index: int, packet_num: int) -> None:
        b = ctx.dialect
        value = packet_num - (1 << 32) if packet_num >= 1 << 31 else packet_num
        ctx.send(b.NamedValueInt(time_boot_ms=0, name=ack_name(index), value=value), urgent=True)


__all__ = ["VrControllerPlugin"]
