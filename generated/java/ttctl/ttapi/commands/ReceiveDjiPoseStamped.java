// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.DjiPoseStamped;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for DJI_POSE_STAMPED: [sender: any] A stamped pose, as in the original TTApi dialect
 * (wire-compatible with it). Orientation is a quaternion x, y, z, w.
 * <p>
 * Accepts the next DJI_POSE_STAMPED addressed to us (target_system 0 or our system id) within the
 * timeout; the future completes with it.
 */
public class ReceiveDjiPoseStamped extends ReceiveCommand {
    public ReceiveDjiPoseStamped(long timeoutMillis) {
        super(DjiPoseStamped.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof DjiPoseStamped)) {
            return false;
        }
        DjiPoseStamped m = (DjiPoseStamped) msg;
        return m.target_system == 0 || m.target_system == ctx.sysId();
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the DJI_POSE_STAMPED received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no DJI_POSE_STAMPED comes in time
    }
}
