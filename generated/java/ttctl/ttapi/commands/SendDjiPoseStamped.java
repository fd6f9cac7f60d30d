// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.DjiPoseStamped;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends DJI_POSE_STAMPED: [sender: any] A stamped pose, as in the original TTApi dialect
 * (wire-compatible with it). Orientation is a quaternion x, y, z, w.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendDjiPoseStamped extends SendCommand {
    /** Receiver system id. (uint8_t) */
    public final int target_system;
    /** Stamp, seconds. [s] (uint32_t) */
    public final long sec;
    /** Stamp, nanoseconds. [ns] (uint32_t) */
    public final long nsec;
    /** What this pose is. (uint8_t; enum {@link ttctl.ttapi.enums.DjiTopicName}) */
    public final int topic_name;
    /** Position x, y, z. [m] (double[3]) */
    public final double[] position;
    /** Orientation quaternion x, y, z, w. (double[4]) */
    public final double[] orientation;

    /**
     * The values to send, packed anew on every try. Arrays are copied: changing yours afterwards
     * changes nothing sent.
     */
    public SendDjiPoseStamped(int target_system, long sec, long nsec, int topic_name, double[] position, double[] orientation) {
        super(DEFAULT_PRIORITY,  // its place in the command queue
              0,  // no retries: it awaits no reply, so it succeeds once sent
              0,  // no reply timeout, for the same reason
              1.0);  // no backoff between retries, there are none
        this.target_system = target_system;
        this.sec = sec;
        this.nsec = nsec;
        this.topic_name = topic_name;
        this.position = position == null ? null : position.clone();
        this.orientation = orientation == null ? null : orientation.clone();
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        DjiPoseStamped msg = new DjiPoseStamped();
        msg.target_system = this.target_system;
        msg.sec = this.sec;
        msg.nsec = this.nsec;
        msg.topic_name = this.topic_name;
        msg.position = this.position == null ? null : this.position.clone();
        msg.orientation = this.orientation == null ? null : this.orientation.clone();
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once DJI_POSE_STAMPED is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when DJI_POSE_STAMPED fails (error is usually a CommandException)
    }
}
