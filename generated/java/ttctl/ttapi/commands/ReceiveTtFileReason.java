// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileReason;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_FILE_REASON: [sender: any] Why a transfer or a request was refused or failed, in
 * words for people: sent just before each TT_FILE_STATUS that carries such a result (refused,
 * failed, not found, request refused), so the sender can say what the receiver knows.
 * <p>
 * Accepts the next TT_FILE_REASON addressed to us (target_system 0 or our system id) within the
 * timeout; the future completes with it.
 */
public class ReceiveTtFileReason extends ReceiveCommand {
    public ReceiveTtFileReason(long timeoutMillis) {
        super(TtFileReason.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtFileReason)) {
            return false;
        }
        TtFileReason m = (TtFileReason) msg;
        return m.target_system == 0 || m.target_system == ctx.sysId();
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_FILE_REASON received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_FILE_REASON comes in time
    }
}
