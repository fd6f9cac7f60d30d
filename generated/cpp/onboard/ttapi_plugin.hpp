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
        dispatcher.on<DjiPoseStamped>(
            [this](const DjiPoseStamped& msg, const Frame& frame) { on_dji_pose_stamped(msg, frame); });
        dispatcher.on<TtActionCommand>(
            [this](const TtActionCommand& msg, const Frame& frame) { on_tt_action_command(msg, frame); });
        dispatcher.on<TtLog>(
            [this](const TtLog& msg, const Frame& frame) { on_tt_log(msg, frame); });
        dispatcher.on<TtVrPose>(
            [this](const TtVrPose& msg, const Frame& frame) { on_tt_vr_pose(msg, frame); });
        dispatcher.on<TtVrController>(
            [this](const TtVrController& msg, const Frame& frame) { on_tt_vr_controller(msg, frame); });
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
};

}  // namespace ttapi::onboard

#endif  // TTCTL_TTAPI_ONBOARD_PLUGIN_HPP
