// Onboard handlers for the ttapi dialect: fill these in.
//
// A skeleton written by ttctl gen from ttapi.xml: it is yours to edit, and `ttctl gen` will
// not overwrite it (unless --force-skeletons). One handler per message the onboard end
// receives (messages tagged [sender: tablet] or [sender: any]);
// register_handlers() binds them to the Dispatcher of the link. Several plugins may handle the
// same message.
//
//     ttapi::Dispatcher dispatcher;
//     ttapi::onboard::TtapiPlugin plugin;
//     plugin.register_handlers(dispatcher);
//     parser.feed(data, n, dispatcher);
#ifndef TTCTL_TTAPI_ONBOARD_PLUGIN_HPP
#define TTCTL_TTAPI_ONBOARD_PLUGIN_HPP

#include "ttapi/ttapi.hpp"

namespace ttapi::onboard {

/// What the onboard computer does with each message it receives.
class TtapiPlugin : public Plugin {
public:
    const char* name() const noexcept override { return "ttapi_onboard"; }

    void register_handlers(Dispatcher& dispatcher) override
    {
        dispatcher.on<TtFileOffer>(
            [this](const TtFileOffer& msg, const Frame& frame) { on_tt_file_offer(msg, frame); });
        dispatcher.on<TtFileStatus>(
            [this](const TtFileStatus& msg, const Frame& frame) { on_tt_file_status(msg, frame); });
        dispatcher.on<TtFileData>(
            [this](const TtFileData& msg, const Frame& frame) { on_tt_file_data(msg, frame); });
        dispatcher.on<TtFileRequest>(
            [this](const TtFileRequest& msg, const Frame& frame) { on_tt_file_request(msg, frame); });
        dispatcher.on<DjiPoseStamped>(
            [this](const DjiPoseStamped& msg, const Frame& frame) { on_dji_pose_stamped(msg, frame); });
        dispatcher.on<TtActionCommand>(
            [this](const TtActionCommand& msg, const Frame& frame) { on_tt_action_command(msg, frame); });
        dispatcher.on<TtLog>(
            [this](const TtLog& msg, const Frame& frame) { on_tt_log(msg, frame); });
        dispatcher.on<TtFileDataWide>(
            [this](const TtFileDataWide& msg, const Frame& frame) { on_tt_file_data_wide(msg, frame); });
        dispatcher.on<TtVrPose>(
            [this](const TtVrPose& msg, const Frame& frame) { on_tt_vr_pose(msg, frame); });
        dispatcher.on<TtVrController>(
            [this](const TtVrController& msg, const Frame& frame) { on_tt_vr_controller(msg, frame); });
        dispatcher.on<TtFileReason>(
            [this](const TtFileReason& msg, const Frame& frame) { on_tt_file_reason(msg, frame); });
    }

    /// TT_FILE_OFFER (id 50000): [sender: any] Offer a file to the receiver, or answer a
    /// TT_FILE_REQUEST. The metadata blob is the file's 32-byte SHA-256 followed by its UTF-8 name
    /// (at most 223 bytes); it is sent in parts (meta_offset, up to 71 bytes each), each part
    /// repeating the other fields. The receiver answers with TT_FILE_STATUS; no file data is sent
    /// before it accepts. Offering a file whose partial state the receiver kept (same name, size
    /// and SHA-256) resumes it, whatever its transfer id was.
    void on_tt_file_offer([[maybe_unused]] const TtFileOffer& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_FILE_OFFER (from system frame.sysid, component frame.compid)
    }

    /// TT_FILE_STATUS (id 50001): [sender: any] The receiver's view of a transfer: sent on
    /// accepting or refusing an offer, while data flows (regularly, when new gaps appear, and when
    /// data stops coming), and on completion. Bytes below received_contiguous have all arrived; in
    /// [region_start, received_end) everything arrived except the listed missing ranges. When there
    /// are more gaps than fit, several statuses describe successive regions. A sender takes a
    /// status for its own only if both transfer_id and meta_check match its offer.
    void on_tt_file_status([[maybe_unused]] const TtFileStatus& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_FILE_STATUS (from system frame.sysid, component frame.compid)
    }

    /// TT_FILE_DATA (id 50002): [sender: any] File bytes in a frame that fills one 100-byte packet
    /// exactly. It carries min(80, size - offset) bytes: the count follows from the offer's size,
    /// so trailing zero bytes may be truncated on the wire.
    void on_tt_file_data([[maybe_unused]] const TtFileData& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_FILE_DATA (from system frame.sysid, component frame.compid)
    }

    /// TT_FILE_REQUEST (id 50003): [sender: any] Ask the peer to send a file (download). The name
    /// is UTF-8, sent in parts like the offer's metadata. The peer answers with TT_FILE_OFFER
    /// (request_id echoed) or TT_FILE_STATUS (transfer_id = request_id, result NOT_FOUND or
    /// REQUEST_REFUSED, with a TT_FILE_REASON).
    void on_tt_file_request([[maybe_unused]] const TtFileRequest& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_FILE_REQUEST (from system frame.sysid, component frame.compid)
    }

    /// DJI_POSE_STAMPED (id 50004): [sender: any] A stamped pose, as in the original TTApi dialect
    /// (wire-compatible with it). Orientation is a quaternion x, y, z, w.
    void on_dji_pose_stamped([[maybe_unused]] const DjiPoseStamped& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle DJI_POSE_STAMPED (from system frame.sysid, component frame.compid)
    }

    /// TT_ACTION_COMMAND (id 50005): [sender: tablet] Ask the onboard computer to perform an
    /// action. Answered by TT_COMMAND_ACK with the same command_id; a retry repeats command_id, so
    /// the action runs once.
    void on_tt_action_command([[maybe_unused]] const TtActionCommand& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_ACTION_COMMAND (from system frame.sysid, component frame.compid)
    }

    /// TT_LOG (id 50008): [sender: any] A log or status line. Text longer than 80 bytes continues
    /// in further messages with the same id and increasing chunk_seq; a chunk with a NUL in text is
    /// the last.
    void on_tt_log([[maybe_unused]] const TtLog& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_LOG (from system frame.sysid, component frame.compid)
    }

    /// TT_FILE_DATA_WIDE (id 50009): [sender: any] [spans-packets] File bytes in a 267-byte frame
    /// that spans packets: less framing per byte, for when the transfer observes little loss. It
    /// carries min(247, size - offset) bytes; trailing zero bytes may be truncated on the wire.
    void on_tt_file_data_wide([[maybe_unused]] const TtFileDataWide& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_FILE_DATA_WIDE (from system frame.sysid, component frame.compid)
    }

    /// TT_VR_POSE (id 50011): [sender: tablet] Pose of a tracked VR device, in ROS REP-103 axes (x
    /// forward, y left, z up; converted from OpenVR's right-handed y-up, -z-forward space).
    /// Orientation is a quaternion x, y, z, w.
    void on_tt_vr_pose([[maybe_unused]] const TtVrPose& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_VR_POSE (from system frame.sysid, component frame.compid)
    }

    /// TT_VR_CONTROLLER (id 50012): [sender: tablet] Controller input, sent when OpenVR's packet
    /// number changes. Axes follow the Joy layout of ROS Vive nodes: trigger, pad_x, pad_y.
    void on_tt_vr_controller([[maybe_unused]] const TtVrController& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_VR_CONTROLLER (from system frame.sysid, component frame.compid)
    }

    /// TT_FILE_REASON (id 50013): [sender: any] Why a transfer or a request was refused or failed,
    /// in words for people: sent just before each TT_FILE_STATUS that carries such a result
    /// (refused, failed, not found, request refused), so the sender can say what the receiver
    /// knows.
    void on_tt_file_reason([[maybe_unused]] const TtFileReason& msg, [[maybe_unused]] const Frame& frame)
    {
        // TODO: handle TT_FILE_REASON (from system frame.sysid, component frame.compid)
    }
};

}  // namespace ttapi::onboard

#endif  // TTCTL_TTAPI_ONBOARD_PLUGIN_HPP
