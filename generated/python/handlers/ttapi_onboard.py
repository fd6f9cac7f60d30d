"""Onboard handlers for the ttapi dialect: fill these in.

A skeleton written by ttctl gen from ttapi.xml: it is yours to edit, and `ttctl gen` will not
overwrite it (unless --force-skeletons). One method per message the onboard end receives
(messages tagged [sender: tablet] or [sender: any]); several
plugins, or several methods, may handle the same message. Load it into the onboard end with
ttctl's plugin system (`ttctl.ends.plugins.load_plugins`).
"""

from __future__ import annotations

from ttctl.ends.plugins import Context, Plugin, handles

from ttapi import messages as m


class TtapiOnboard(Plugin):
    """What the onboard computer does with each message it receives."""

    @handles(m.TtFileOffer)
    def on_tt_file_offer(self, msg: m.TtFileOffer, ctx: Context) -> None:
        """[sender: any] Offer a file to the receiver, or answer a TT_FILE_REQUEST. The metadata blob is the file's 32-byte SHA-256 followed by its UTF-8 name (at most 223 bytes); it is sent in parts (meta_offset, up to 71 bytes each), each part repeating the other fields. The receiver answers with TT_FILE_STATUS; no file data is sent before it accepts. Offering a file whose partial state the receiver kept (same name, size and SHA-256) resumes it, whatever its transfer id was."""
        ctx.log(f"TT_FILE_OFFER from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtFileStatus)
    def on_tt_file_status(self, msg: m.TtFileStatus, ctx: Context) -> None:
        """[sender: any] The receiver's view of a transfer: sent on accepting or refusing an offer, while data flows (regularly, when new gaps appear, and when data stops coming), and on completion. Bytes below received_contiguous have all arrived; in [region_start, received_end) everything arrived except the listed missing ranges. When there are more gaps than fit, several statuses describe successive regions. A sender takes a status for its own only if both transfer_id and meta_check match its offer."""
        ctx.log(f"TT_FILE_STATUS from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtFileData)
    def on_tt_file_data(self, msg: m.TtFileData, ctx: Context) -> None:
        """[sender: any] File bytes in a frame that fills one 100-byte packet exactly. It carries min(80, size - offset) bytes: the count follows from the offer's size, so trailing zero bytes may be truncated on the wire."""
        ctx.log(f"TT_FILE_DATA from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtFileRequest)
    def on_tt_file_request(self, msg: m.TtFileRequest, ctx: Context) -> None:
        """[sender: any] Ask the peer to send a file (download). The name is UTF-8, sent in parts like the offer's metadata. The peer answers with TT_FILE_OFFER (request_id echoed) or TT_FILE_STATUS (transfer_id = request_id, result NOT_FOUND or REQUEST_REFUSED, with a TT_FILE_REASON)."""
        ctx.log(f"TT_FILE_REQUEST from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

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

    @handles(m.TtFileDataWide)
    def on_tt_file_data_wide(self, msg: m.TtFileDataWide, ctx: Context) -> None:
        """[sender: any] [spans-packets] File bytes in a 267-byte frame that spans packets: less framing per byte, for when the transfer observes little loss. It carries min(247, size - offset) bytes; trailing zero bytes may be truncated on the wire."""
        ctx.log(f"TT_FILE_DATA_WIDE from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtVrPose)
    def on_tt_vr_pose(self, msg: m.TtVrPose, ctx: Context) -> None:
        """[sender: tablet] Pose of a tracked VR device, in ROS REP-103 axes (x forward, y left, z up; converted from OpenVR's right-handed y-up, -z-forward space). Orientation is a quaternion x, y, z, w."""
        ctx.log(f"TT_VR_POSE from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtVrController)
    def on_tt_vr_controller(self, msg: m.TtVrController, ctx: Context) -> None:
        """[sender: tablet] Controller input, sent when OpenVR's packet number changes. Axes follow the Joy layout of ROS Vive nodes: trigger, pad_x, pad_y."""
        ctx.log(f"TT_VR_CONTROLLER from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")

    @handles(m.TtFileReason)
    def on_tt_file_reason(self, msg: m.TtFileReason, ctx: Context) -> None:
        """[sender: any] Why a transfer or a request was refused or failed, in words for people: sent just before each TT_FILE_STATUS that carries such a result (refused, failed, not found, request refused), so the sender can say what the receiver knows."""
        ctx.log(f"TT_FILE_REASON from {msg.get_srcSystem()}/{msg.get_srcComponent()} not handled yet: {msg!r}")
