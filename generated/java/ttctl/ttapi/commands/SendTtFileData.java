// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileData;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_FILE_DATA: [sender: any] File bytes in a frame that fills one 100-byte packet exactly.
 * It carries min(80, size - offset) bytes: the count follows from the offer's size, so trailing
 * zero bytes may be truncated on the wire.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtFileData extends SendCommand {
    /** Transfer id from the offer. (uint32_t) */
    public final long transfer_id;
    /** Offset of data in the file. [bytes] (uint32_t) */
    public final long offset;
    /** File bytes. (uint8_t[80]) */
    public final byte[] data;

    public SendTtFileData(long transfer_id, long offset, byte[] data) {
        super(DEFAULT_PRIORITY, 0, 0, 1.0);
        this.transfer_id = transfer_id;
        this.offset = offset;
        this.data = data;
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtFileData msg = new TtFileData();
        msg.transfer_id = this.transfer_id;
        msg.offset = this.offset;
        msg.data = this.data;
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_FILE_DATA is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_FILE_DATA fails (error is usually a CommandException)
    }
}
