// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileDataWide;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_FILE_DATA_WIDE: [sender: any] [spans-packets] File bytes in a 267-byte frame that spans
 * packets: less framing per byte, for when the transfer observes little loss. It carries min(247,
 * size - offset) bytes; trailing zero bytes may be truncated on the wire.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtFileDataWide extends SendCommand {
    /** Transfer id from the offer. (uint32_t) */
    public final long transfer_id;
    /** Offset of data in the file. [bytes] (uint32_t) */
    public final long offset;
    /** File bytes. (uint8_t[247]) */
    public final byte[] data;

    public SendTtFileDataWide(long transfer_id, long offset, byte[] data) {
        super(DEFAULT_PRIORITY, 0, 0, 1.0);
        this.transfer_id = transfer_id;
        this.offset = offset;
        this.data = data;
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtFileDataWide msg = new TtFileDataWide();
        msg.transfer_id = this.transfer_id;
        msg.offset = this.offset;
        msg.data = this.data;
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_FILE_DATA_WIDE is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_FILE_DATA_WIDE fails (error is usually a CommandException)
    }
}
