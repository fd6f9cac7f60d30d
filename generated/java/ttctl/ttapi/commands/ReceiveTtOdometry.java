// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtOdometry;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_ODOMETRY: [sender: onboard] Pose and twist estimate (ROS nav_msgs/Odometry without
 * full covariances). Orientation is a quaternion x, y, z, w.
 * <p>
 * Accepts the next TT_ODOMETRY within the timeout; the future completes with it.
 */
public class ReceiveTtOdometry extends ReceiveCommand {
    public ReceiveTtOdometry(long timeoutMillis) {
        super(TtOdometry.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtOdometry)) {
            return false;
        }
        return true;
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_ODOMETRY received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_ODOMETRY comes in time
    }
}
