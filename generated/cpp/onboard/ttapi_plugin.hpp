// Onboard handlers for the ttapi dialect: fill these in.
//
// A skeleton written by ttctl gen from ttapi.xml: it is yours to edit, and `ttctl gen` will
// not overwrite it (unless --force-skeletons). One handler per message the onboard end
// receives (messages tagged [sender: tablet] or [sender: any]);
// register_handlers() binds them to the Dispatcher of the link. Several plugins may handle the
// same message. Each handler gets an Outbox to send any message of the dialect, a reply say:
// out.send(ack). Wire the Outbox to your link once: its send_payload() frames the payload with
// an Encoder and cuts the frame into DTT packets with a Packetizer, which you hand to the DJI
// SDK. Packets that arrive go to a PacketReceiver (a frame may span packets; a Parser does not
// know packet boundaries):
//
//     class LinkOutbox : public ttapi::Outbox {
//     public:
//         bool send_payload(const ttapi::MessageInfo& info, const std::uint8_t* payload,
//                           std::size_t n) override
//         {
//             std::uint8_t frame[ttapi::MAX_FRAME];
//             const std::size_t len = encoder.encode_payload(info, payload, n, frame, sizeof frame);
//             packetizer.add(frame, len, send_packet);  // send_packet(const std::uint8_t*, std::size_t)
//             packetizer.flush(send_packet);
//             return len != 0;
//         }
//         ttapi::Encoder encoder{1, 191};  // this end's system and component id
//         ttapi::Packetizer packetizer;  // packets of at most 100 bytes
//     };
//
//     LinkOutbox outbox;
//     ttapi::Dispatcher dispatcher(outbox);
//     ttapi::onboard::TtapiPlugin plugin;
//     plugin.register_handlers(dispatcher);
//     ttapi::PacketReceiver receiver;
//     receiver.feed(packet, n, dispatcher);  // for each DTT packet as it arrives
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
        dispatcher.on<DjiPoseStamped>([this](const DjiPoseStamped& msg, const Frame& frame, Outbox& out) {
            on_dji_pose_stamped(msg, frame, out);
        });
        dispatcher.on<TtActionCommand>([this](const TtActionCommand& msg, const Frame& frame, Outbox& out) {
            on_tt_action_command(msg, frame, out);
        });
        dispatcher.on<TtLog>([this](const TtLog& msg, const Frame& frame, Outbox& out) {
            on_tt_log(msg, frame, out);
        });
        dispatcher.on<TtVrPose>([this](const TtVrPose& msg, const Frame& frame, Outbox& out) {
            on_tt_vr_pose(msg, frame, out);
        });
        dispatcher.on<TtVrController>([this](const TtVrController& msg, const Frame& frame, Outbox& out) {
            on_tt_vr_controller(msg, frame, out);
        });
    }

    /// DJI_POSE_STAMPED (id 50004): [sender: any] A stamped pose, as in the original TTApi dialect
    /// (wire-compatible with it). Orientation is a quaternion x, y, z, w.
    ///
    /// Fields of msg:
    ///   - target_system (uint8_t): Receiver system id.
    ///   - sec (uint32_t, s): Stamp, seconds.
    ///   - nsec (uint32_t, ns): Stamp, nanoseconds.
    ///   - topic_name (uint8_t, enum DjiTopicName): What this pose is.
    ///   - position (double[3], m): Position x, y, z.
    ///   - orientation (double[4]): Orientation quaternion x, y, z, w.
    void on_dji_pose_stamped([[maybe_unused]] const DjiPoseStamped& msg, [[maybe_unused]] const Frame& frame,
            [[maybe_unused]] Outbox& out)
    {
        // TODO: handle DJI_POSE_STAMPED (from system frame.sysid, component frame.compid); out.send(...) replies
    }

    /// TT_ACTION_COMMAND (id 50005): [sender: tablet] Ask the onboard computer to perform an
    /// action. Answered by TT_COMMAND_ACK with the same command_id; a retry repeats command_id, so
    /// the action runs once.
    ///
    /// Fields of msg:
    ///   - target_system (uint8_t): Receiver system id.
    ///   - target_component (uint8_t): Receiver component id.
    ///   - command_id (uint16_t): Sender-chosen id, repeated on retries.
    ///   - action (uint8_t, enum TtAction): What to do.
    ///   - time_usec (uint64_t, us): Sender's clock (UNIX epoch) when the command was issued.
    ///   - param (float[4]): Action parameters, see TT_ACTION.
    ///   - argument (char[48]): Action argument, e.g. the mission file of FLY_TRAJECTORY.
    void on_tt_action_command([[maybe_unused]] const TtActionCommand& msg, [[maybe_unused]] const Frame& frame,
            [[maybe_unused]] Outbox& out)
    {
        // TODO: handle TT_ACTION_COMMAND (from system frame.sysid, component frame.compid); out.send(...) replies
    }

    /// TT_LOG (id 50008): [sender: any] A log or status line. Text longer than 80 bytes continues
    /// in further messages with the same id and increasing chunk_seq; a chunk with a NUL in text is
    /// the last.
    ///
    /// Fields of msg:
    ///   - time_boot_ms (uint32_t, ms): Sender's time since boot.
    ///   - id (uint16_t): Line id, the same for every chunk of one line (0: single chunk).
    ///   - severity (uint8_t, enum MavSeverity): Severity.
    ///   - chunk_seq (uint8_t): Chunk number within the line, from 0.
    ///   - text (char[80]): UTF-8 text, NUL-terminated if shorter than 80 bytes.
    void on_tt_log([[maybe_unused]] const TtLog& msg, [[maybe_unused]] const Frame& frame,
            [[maybe_unused]] Outbox& out)
    {
        // TODO: handle TT_LOG (from system frame.sysid, component frame.compid); out.send(...) replies
    }

    /// TT_VR_POSE (id 50011): [sender: tablet] Pose of a tracked VR device, in ROS REP-103 axes (x
    /// forward, y left, z up; converted from OpenVR's right-handed y-up, -z-forward space).
    /// Orientation is a quaternion x, y, z, w.
    ///
    /// Fields of msg:
    ///   - time_usec (uint64_t, us): Time of the sample (UNIX epoch).
    ///   - device (uint8_t, enum TtVrDevice): Device class.
    ///   - role (uint8_t, enum TtVrRole): Controller hand, NONE for other devices.
    ///   - index (uint8_t): OpenVR device index.
    ///   - flags (uint8_t, enum TtVrPoseFlags): Pose validity.
    ///   - position (float[3], m): Position x, y, z.
    ///   - orientation (float[4]): Orientation quaternion x, y, z, w.
    ///   - velocity (float[3], m/s): Linear velocity x, y, z.
    ///   - angular_velocity (float[3], rad/s): Angular velocity x, y, z.
    void on_tt_vr_pose([[maybe_unused]] const TtVrPose& msg, [[maybe_unused]] const Frame& frame,
            [[maybe_unused]] Outbox& out)
    {
        // TODO: handle TT_VR_POSE (from system frame.sysid, component frame.compid); out.send(...) replies
    }

    /// TT_VR_CONTROLLER (id 50012): [sender: tablet] Controller input, sent when OpenVR's packet
    /// number changes. Axes follow the Joy layout of ROS Vive nodes: trigger, pad_x, pad_y.
    ///
    /// Fields of msg:
    ///   - time_usec (uint64_t, us): Time of the sample (UNIX epoch).
    ///   - packet_num (uint32_t): OpenVR unPacketNum of this state.
    ///   - index (uint8_t): OpenVR device index.
    ///   - role (uint8_t, enum TtVrRole): Controller hand.
    ///   - trigger (float): Trigger, 0..1.
    ///   - pad_x (float): Trackpad x, -1..1.
    ///   - pad_y (float): Trackpad y, -1..1.
    ///   - buttons (uint16_t, enum TtVrButtons): Buttons held.
    void on_tt_vr_controller([[maybe_unused]] const TtVrController& msg, [[maybe_unused]] const Frame& frame,
            [[maybe_unused]] Outbox& out)
    {
        // TODO: handle TT_VR_CONTROLLER (from system frame.sysid, component frame.compid); out.send(...) replies
    }
};

}  // namespace ttapi::onboard

#endif  // TTCTL_TTAPI_ONBOARD_PLUGIN_HPP
