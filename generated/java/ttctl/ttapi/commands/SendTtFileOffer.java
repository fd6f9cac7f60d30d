// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileOffer;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_FILE_OFFER: [sender: any] Offer a file to the receiver, or answer a TT_FILE_REQUEST. The
 * metadata blob is the file's 32-byte SHA-256 followed by its UTF-8 name (at most 223 bytes); it is
 * sent in parts (meta_offset, up to 71 bytes each), each part repeating the other fields. The
 * receiver answers with TT_FILE_STATUS; no file data is sent before it accepts. Offering a file
 * whose partial state the receiver kept (same name, size and SHA-256) resumes it, whatever its
 * transfer id was.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtFileOffer extends SendCommand {
    /** Receiver system id. (uint8_t) */
    public final int target_system;
    /** Receiver component id. (uint8_t) */
    public final int target_component;
    /**
     * Sender-chosen random nonce, never 0, new for every transfer (a restart or resume gets a new
     * one): it names the transfer in every frame, so that no other sender, process or earlier run
     * can reuse it by accident. (uint32_t)
     */
    public final long transfer_id;
    /** The TT_FILE_REQUEST (its request_id) this answers, 0 if unsolicited. (uint32_t) */
    public final long request_id;
    /** File size. [bytes] (uint32_t) */
    public final long size;
    /** Offer flags. (uint8_t; enum {@link ttctl.ttapi.enums.TtFileFlags}) */
    public final int flags;
    /** Length of the whole metadata blob (32 + name length). [bytes] (uint8_t) */
    public final int meta_length;
    /** Offset of this part in the metadata blob. [bytes] (uint8_t) */
    public final int meta_offset;
    /** Part of the metadata blob. (uint8_t[71]) */
    public final byte[] meta;

    public SendTtFileOffer(int target_system, int target_component, long transfer_id, long request_id, long size, int flags, int meta_length, int meta_offset, byte[] meta) {
        super(DEFAULT_PRIORITY, 0, 0, 1.0);
        this.target_system = target_system;
        this.target_component = target_component;
        this.transfer_id = transfer_id;
        this.request_id = request_id;
        this.size = size;
        this.flags = flags;
        this.meta_length = meta_length;
        this.meta_offset = meta_offset;
        this.meta = meta;
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtFileOffer msg = new TtFileOffer();
        msg.target_system = this.target_system;
        msg.target_component = this.target_component;
        msg.transfer_id = this.transfer_id;
        msg.request_id = this.request_id;
        msg.size = this.size;
        msg.flags = this.flags;
        msg.meta_length = this.meta_length;
        msg.meta_offset = this.meta_offset;
        msg.meta = this.meta;
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_FILE_OFFER is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_FILE_OFFER fails (error is usually a CommandException)
    }
}
