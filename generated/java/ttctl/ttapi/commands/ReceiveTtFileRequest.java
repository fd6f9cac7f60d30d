// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileRequest;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_FILE_REQUEST: [sender: any] Ask the peer to send a file (download). The name is
 * UTF-8, sent in parts like the offer's metadata. The peer answers with TT_FILE_OFFER (request_id
 * echoed) or TT_FILE_STATUS (transfer_id = request_id, result NOT_FOUND or REQUEST_REFUSED, with a
 * TT_FILE_REASON).
 * <p>
 * Accepts the next TT_FILE_REQUEST addressed to us (target_system 0 or our system id) within the
 * timeout; the future completes with it.
 */
public class ReceiveTtFileRequest extends ReceiveCommand {
    public ReceiveTtFileRequest(long timeoutMillis) {
        super(TtFileRequest.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtFileRequest)) {
            return false;
        }
        TtFileRequest m = (TtFileRequest) msg;
        return m.target_system == 0 || m.target_system == ctx.sysId();
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_FILE_REQUEST received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_FILE_REQUEST comes in time
    }
}
