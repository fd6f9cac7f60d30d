// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileStatus;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_FILE_STATUS: [sender: any] The receiver's view of a transfer: sent on accepting or
 * refusing an offer, while data flows (regularly, when new gaps appear, and when data stops
 * coming), and on completion. Bytes below received_contiguous have all arrived; in [region_start,
 * received_end) everything arrived except the listed missing ranges. When there are more gaps than
 * fit, several statuses describe successive regions. A sender takes a status for its own only if
 * both transfer_id and meta_check match its offer.
 * <p>
 * Accepts the next TT_FILE_STATUS addressed to us (target_system 0 or our system id) within the
 * timeout; the future completes with it.
 */
public class ReceiveTtFileStatus extends ReceiveCommand {
    public ReceiveTtFileStatus(long timeoutMillis) {
        super(TtFileStatus.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtFileStatus)) {
            return false;
        }
        TtFileStatus m = (TtFileStatus) msg;
        return m.target_system == 0 || m.target_system == ctx.sysId();
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_FILE_STATUS received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_FILE_STATUS comes in time
    }
}
