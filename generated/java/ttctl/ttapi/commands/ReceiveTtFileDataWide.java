// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileDataWide;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_FILE_DATA_WIDE: [sender: any] [spans-packets] File bytes in a 267-byte frame that
 * spans packets: less framing per byte, for when the transfer observes little loss. It carries
 * min(247, size - offset) bytes; trailing zero bytes may be truncated on the wire.
 * <p>
 * Accepts the next TT_FILE_DATA_WIDE within the timeout; the future completes with it.
 */
public class ReceiveTtFileDataWide extends ReceiveCommand {
    public ReceiveTtFileDataWide(long timeoutMillis) {
        super(TtFileDataWide.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtFileDataWide)) {
            return false;
        }
        return true;
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_FILE_DATA_WIDE received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_FILE_DATA_WIDE comes in time
    }
}
