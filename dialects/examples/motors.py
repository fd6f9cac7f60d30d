"""The robot's motors, onboard: every KR_MOTOR_CONTROL is obeyed and answered with a
KR_MOTOR_STATUS carrying its seq, to whoever sent it: the tablet, or a ground station on its link
(the README's walkthrough, tests/test_own_dialect.py and tests/test_gcs_dialect.py).

    ttctl emulate onboard --dialect robolab.xml --plugin motors.py
"""

from __future__ import annotations

from robolab import enums as e
from robolab import messages as m

from ttctl.ends.plugins import Context, Plugin, handles


class Motors(Plugin):
    def __init__(self) -> None:
        self.dir, self.speed, self.handled = e.KrVehicleDir.KR_VEHICLE_DIR_STOP, 0, 0

    @handles(m.KrMotorControl)
    def on_kr_motor_control(self, msg: m.KrMotorControl, ctx: Context) -> None:
        self.dir, self.speed = e.KrVehicleDir(msg.dir), msg.speed
        self.handled += 1
        ctx.log(f"motors: seq {msg.seq}: {self.dir.name} at {self.speed} %")
        ctx.reply(m.KrMotorStatus(target_system=msg.get_srcSystem(), seq=msg.seq, dir=self.dir, speed=self.speed,
                                  rpm=self.speed * 12.5, note="ok"), urgent=True)
