// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtLog;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_LOG: [sender: any] A log or status line. Text longer than 80 bytes continues in
 * further messages with the same id and increasing chunk_seq; a chunk with a NUL in text is the
 * last.
 * <p>
 * Accepts the next TT_LOG within the timeout; the future completes with it.
 */
public class ReceiveTtLog extends ReceiveCommand {
    public ReceiveTtLog(long timeoutMillis) {
        super(TtLog.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtLog)) {
            return false;
        }
        return true;
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_LOG received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_LOG comes in time
    }
}
