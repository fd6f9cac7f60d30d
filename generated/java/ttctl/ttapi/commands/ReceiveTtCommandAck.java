// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtCommandAck;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_COMMAND_ACK: [sender: onboard] Answer to a TT_ACTION_COMMAND, also repeated for
 * retries of an already executed command_id.
 * <p>
 * Accepts the next TT_COMMAND_ACK addressed to us (target_system 0 or our system id) within the
 * timeout; the future completes with it.
 */
public class ReceiveTtCommandAck extends ReceiveCommand {
    public ReceiveTtCommandAck(long timeoutMillis) {
        super(TtCommandAck.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtCommandAck)) {
            return false;
        }
        TtCommandAck m = (TtCommandAck) msg;
        return m.target_system == 0 || m.target_system == ctx.sysId();
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_COMMAND_ACK received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_COMMAND_ACK comes in time
    }
}
