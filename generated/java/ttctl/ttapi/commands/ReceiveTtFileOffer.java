// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileOffer;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.ReceiveCommand;

/**
 * Waits for TT_FILE_OFFER: [sender: any] Offer a file to the receiver, or answer a TT_FILE_REQUEST.
 * The metadata blob is the file's 32-byte SHA-256 followed by its UTF-8 name (at most 223 bytes);
 * it is sent in parts (meta_offset, up to 71 bytes each), each part repeating the other fields. The
 * receiver answers with TT_FILE_STATUS; no file data is sent before it accepts. Offering a file
 * whose partial state the receiver kept (same name, size and SHA-256) resumes it, whatever its
 * transfer id was.
 * <p>
 * Accepts the next TT_FILE_OFFER addressed to us (target_system 0 or our system id) within the
 * timeout; the future completes with it.
 */
public class ReceiveTtFileOffer extends ReceiveCommand {
    public ReceiveTtFileOffer(long timeoutMillis) {
        super(TtFileOffer.MSG_ID, timeoutMillis);
    }

    @Override
    protected boolean accept(MavlinkMessage msg, CommandContext ctx) {
        if (!super.accept(msg, ctx) || !(msg instanceof TtFileOffer)) {
            return false;
        }
        TtFileOffer m = (TtFileOffer) msg;
        return m.target_system == 0 || m.target_system == ctx.sysId();
    }

    @Override
    protected void onSuccess(MavlinkMessage msg) {
        // TODO: handle the TT_FILE_OFFER received
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when no TT_FILE_OFFER comes in time
    }
}
