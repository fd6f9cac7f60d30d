// Onboard handlers for the ttapi dialect: fill these in.
//
// A skeleton written by ttctl gen from ttapi.xml: it is yours to edit, and `ttctl gen` will
// not overwrite it (unless --force-skeletons). It plugs into a link::Node (ttapi/node.hpp),
// the onboard end of the link, which handles file transfer, command acks and the heartbeat
// itself. Here: one handler per message the onboard end receives (those tagged
// [sender: tablet] or [sender: any]), and on_command(), the action of TT_ACTION_COMMAND: the
// node runs it once per command and sends the ack (a retry gets the recorded ack). Handlers
// reply through their NodeContext: ctx.send(msg) at control priority, ctx.telemetry(msg)
// behind it, ctx.log(text).
//
// A program on UDP (ttctl's emulated radio, a laptop), with ttapi/udp_link.hpp:
//
//     ttapi::link::NodeConfig cfg;  // system 1, component 240, paced to the M100's downlink
//     cfg.inbox = "inbox";  // files the tablet sends land here (a jail: nothing outside it)
//     cfg.serve = "outbox";  // files the tablet may fetch
//     ttapi::link::Node node(cfg);
//     ttapi::onboard::TtapiPlugin plugin;
//     node.add(plugin);
//     ttapi::link::Words why;
//     ttapi::link::UdpLink udp(node);
//     if (!node.start(why) || !udp.open("udpin:0.0.0.0:14560", why)) {
//         std::fprintf(stderr, "%s\n", why.c_str());
//         return 1;
//     }
//     std::atomic<bool> stop{false};
//     udp.run(stop);
//
// On the drone, DJI's Onboard SDK 4 carries the packets instead (see DttLink in dtt_link.hpp, which
// node.hpp includes).
#ifndef TTCTL_TTAPI_ONBOARD_PLUGIN_HPP
#define TTCTL_TTAPI_ONBOARD_PLUGIN_HPP

#include "ttapi/node.hpp"

namespace ttapi::onboard {

/// What the onboard computer does with each message it receives, and with commands.
class TtapiPlugin : public link::NodePlugin {
public:
    const char* name() const noexcept override { return "ttapi_onboard"; }

    void attach(link::Node& node) override
    {
        node.on<DjiPoseStamped>([this](const DjiPoseStamped& msg, const Frame& frame, link::NodeContext& ctx) {
            on_dji_pose_stamped(msg, frame, ctx);
        });
        node.on<TtLog>([this](const TtLog& msg, const Frame& frame, link::NodeContext& ctx) {
            on_tt_log(msg, frame, ctx);
        });
        node.on<TtVrPose>([this](const TtVrPose& msg, const Frame& frame, link::NodeContext& ctx) {
            on_tt_vr_pose(msg, frame, ctx);
        });
        node.on<TtVrController>([this](const TtVrController& msg, const Frame& frame, link::NodeContext& ctx) {
            on_tt_vr_controller(msg, frame, ctx);
        });
        node.on_command([this](const TtActionCommand& cmd, const Frame& frame, link::NodeContext& ctx) {
            return on_command(cmd, frame, ctx);
        });
    }

    /// TT_ACTION_COMMAND (id 50005): [sender: tablet] Ask the onboard computer to perform an
    /// action. Answered by TT_COMMAND_ACK with the same command_id; a retry repeats command_id, so
    /// the action runs once.
    /// Run once per command: return TT_RESULT_ACCEPTED (or IN_PROGRESS, DONE) only for an action
    /// this vehicle carries out; a refusal (DENIED, BUSY, UNSUPPORTED, FAILED) may say why in
    /// words, which go to the tablet as a TT_LOG line ahead of the ack. Return quickly: start long
    /// actions elsewhere (IN_PROGRESS) and report with ctx.log() or a message of your own.
    ///
    /// Fields of cmd:
    ///   - target_system (uint8_t): Receiver system id.
    ///   - target_component (uint8_t): Receiver component id.
    ///   - command_id (uint16_t): Sender-chosen id, repeated on retries.
    ///   - action (uint8_t, enum TtAction): What to do.
    ///   - time_usec (uint64_t, us): Sender's clock (UNIX epoch) when the command was issued.
    ///   - param (float[4]): Action parameters, see TT_ACTION.
    ///   - argument (char[48]): Action argument, e.g. the mission file of FLY_TRAJECTORY.
    link::CommandOutcome on_command([[maybe_unused]] const TtActionCommand& cmd, [[maybe_unused]] const Frame& frame,
                                    [[maybe_unused]] link::NodeContext& ctx)
    {
        // TODO: carry out cmd.action (a TtAction) with cmd.param and cmd.argument, from system frame.sysid
        return {TtResult::TT_RESULT_UNSUPPORTED, "not implemented on this vehicle yet"};
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
            [[maybe_unused]] link::NodeContext& ctx)
    {
        // The tablet's set-point (topic SETPOINT) waits for an answer, or its goto fails: fly it
        // once per stamp and echo it to the sender, or refuse it in your words (a TT_LOG warning
        // "set-point refused: ..."), in one call; other topics are not_setpoint, yours below:
        //
        //     if (ctx.setpoint(msg, frame, [&]() -> std::optional<std::string> {
        //             if (msg.position[2] < 0.5) {  // north, east, altitude above home, in m
        //                 return "altitude below 0.5 m: land instead";
        //             }
        //             // fly to msg.position
        //             return std::nullopt;
        //         }) != link::SetpointVerdict::not_setpoint) {
        //         return;
        //     }
        // TODO: handle DJI_POSE_STAMPED (from system frame.sysid, component frame.compid); ctx.send(...) replies
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
            [[maybe_unused]] link::NodeContext& ctx)
    {
        // TODO: handle TT_LOG (from system frame.sysid, component frame.compid); ctx.send(...) replies
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
            [[maybe_unused]] link::NodeContext& ctx)
    {
        // TODO: handle TT_VR_POSE (from system frame.sysid, component frame.compid); ctx.send(...) replies
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
            [[maybe_unused]] link::NodeContext& ctx)
    {
        // TODO: handle TT_VR_CONTROLLER (from system frame.sysid, component frame.compid); ctx.send(...) replies
    }
};

}  // namespace ttapi::onboard

#endif  // TTCTL_TTAPI_ONBOARD_PLUGIN_HPP
