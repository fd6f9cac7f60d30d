// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileData;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_FILE_DATA: [sender: any] File bytes in a frame that fills one 100-byte packet
 * exactly. It carries min(80, size - offset) bytes: the count follows from the offer's size, so
 * trailing zero bytes may be truncated on the wire.
 * <p>
 * Accepts the next TT_FILE_DATA within the timeout; the future completes with it.
 */
public class ReceiveTtFileData extends ReceiveCommand {
    public ReceiveTtFileData(long timeoutMillis) {
        super(TtFileData.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtFileData)) {
            return false;
        }
        return true;
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_FILE_DATA received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_FILE_DATA comes in time
    }
}
