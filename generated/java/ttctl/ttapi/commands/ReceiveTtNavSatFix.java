// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtNavSatFix;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_NAV_SAT_FIX: [sender: onboard] GNSS fix (ROS sensor_msgs/NavSatFix).
 * <p>
 * Accepts the next TT_NAV_SAT_FIX within the timeout; the future completes with it.
 */
public class ReceiveTtNavSatFix extends ReceiveCommand {
    public ReceiveTtNavSatFix(long timeoutMillis) {
        super(TtNavSatFix.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtNavSatFix)) {
            return false;
        }
        return true;
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_NAV_SAT_FIX received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_NAV_SAT_FIX comes in time
    }
}
