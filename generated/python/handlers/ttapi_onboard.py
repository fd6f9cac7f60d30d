"""Onboard handlers for the ttapi dialect: fill these in.

A skeleton written by ttctl gen from ttapi.xml: it is yours to edit, and `ttctl gen` will not
overwrite it (unless --force-skeletons). One method per message the onboard end receives
(messages tagged [sender: tablet] or [sender: any]); several
plugins, or several methods, may handle the same message. Run it in the onboard end, which
speaks this dialect and puts its bindings (ttapi) on the import path; from the folder
`ttctl gen` wrote into:

    ttctl emulate onboard --dialect path/to/ttapi.xml --plugin python/handlers/ttapi_onboard.py

A handler answers with `ctx.send(m.SomeMessage(...))` (any message of the dialect, to the
tablet), tells ground stations with `ctx.send_gcs(...)`, logs with `ctx.log(...)`, and
`ctx.every(seconds, fn)` in `start(self, ctx)` runs something periodically.
"""

from __future__ import annotations

from ttctl.ends.plugins import Context, Plugin, handles

from ttapi import messages as m


class TtapiOnboard(Plugin):
    """What the onboard computer does with each message it receives."""

    @handles(m.DjiPoseStamped)
    def on_dji_pose_stamped(self, msg: m.DjiPoseStamped, ctx: Context) -> None:
        """[sender: any] A stamped pose, as in the original TTApi dialect (wire-compatible with it). Orientation is a quaternion x, y, z, w."""
        ctx.log(f"DJI_POSE_STAMPED from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtActionCommand)
    def on_tt_action_command(self, msg: m.TtActionCommand, ctx: Context) -> None:
        """[sender: tablet] Ask the onboard computer to perform an action. Answered by TT_COMMAND_ACK with the same command_id; a retry repeats command_id, so the action runs once."""
        ctx.log(f"TT_ACTION_COMMAND from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtLog)
    def on_tt_log(self, msg: m.TtLog, ctx: Context) -> None:
        """[sender: any] A log or status line. Text longer than 80 bytes continues in further messages with the same id and increasing chunk_seq; a chunk with a NUL in text is the last."""
        ctx.log(f"TT_LOG from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtVrPose)
    def on_tt_vr_pose(self, msg: m.TtVrPose, ctx: Context) -> None:
        """[sender: tablet] Pose of a tracked VR device, in ROS REP-103 axes (x forward, y left, z up; converted from OpenVR's right-handed y-up, -z-forward space). Orientation is a quaternion x, y, z, w."""
        ctx.log(f"TT_VR_POSE from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtVrController)
    def on_tt_vr_controller(self, msg: m.TtVrController, ctx: Context) -> None:
        """[sender: tablet] Controller input, sent when OpenVR's packet number changes. Axes follow the Joy layout of ROS Vive nodes: trigger, pad_x, pad_y."""
        ctx.log(f"TT_VR_CONTROLLER from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")
