// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtVrPose;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_VR_POSE: [sender: tablet] Pose of a tracked VR device, in ROS REP-103 axes (x forward, y
 * left, z up; converted from OpenVR's right-handed y-up, -z-forward space). Orientation is a
 * quaternion x, y, z, w.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtVrPose extends SendCommand {
    /** Time of the sample (UNIX epoch). [us] (uint64_t) */
    public final long time_usec;
    /** Device class. (uint8_t; enum {@link ttctl.ttapi.enums.TtVrDevice}) */
    public final int device;
    /**
     * Controller hand, NONE for other devices. (uint8_t; enum {@link ttctl.ttapi.enums.TtVrRole})
     */
    public final int role;
    /** OpenVR device index. (uint8_t) */
    public final int index;
    /** Pose validity. (uint8_t; enum {@link ttctl.ttapi.enums.TtVrPoseFlags}) */
    public final int flags;
    /** Position x, y, z. [m] (float[3]) */
    public final float[] position;
    /** Orientation quaternion x, y, z, w. (float[4]) */
    public final float[] orientation;
    /** Linear velocity x, y, z. [m/s] (float[3]) */
    public final float[] velocity;
    /** Angular velocity x, y, z. [rad/s] (float[3]) */
    public final float[] angular_velocity;

    /**
     * The values to send, packed anew on every try. Arrays are copied: changing yours afterwards
     * changes nothing sent.
     */
    public SendTtVrPose(long time_usec, int device, int role, int index, int flags, float[] position, float[] orientation, float[] velocity, float[] angular_velocity) {
        super(DEFAULT_PRIORITY,  // its place in the command queue
              0,  // no retries: it awaits no reply, so it succeeds once sent
              0,  // no reply timeout, for the same reason
              1.0);  // no backoff between retries, there are none
        this.time_usec = time_usec;
        this.device = device;
        this.role = role;
        this.index = index;
        this.flags = flags;
        this.position = position == null ? null : position.clone();
        this.orientation = orientation == null ? null : orientation.clone();
        this.velocity = velocity == null ? null : velocity.clone();
        this.angular_velocity = angular_velocity == null ? null : angular_velocity.clone();
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtVrPose msg = new TtVrPose();
        msg.time_usec = this.time_usec;
        msg.device = this.device;
        msg.role = this.role;
        msg.index = this.index;
        msg.flags = this.flags;
        msg.position = this.position == null ? null : this.position.clone();
        msg.orientation = this.orientation == null ? null : this.orientation.clone();
        msg.velocity = this.velocity == null ? null : this.velocity.clone();
        msg.angular_velocity = this.angular_velocity == null ? null : this.angular_velocity.clone();
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_VR_POSE is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_VR_POSE fails (error is usually a CommandException)
    }
}
