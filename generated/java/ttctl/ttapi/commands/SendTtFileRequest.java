// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileRequest;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_FILE_REQUEST: [sender: any] Ask the peer to send a file (download). The name is UTF-8,
 * sent in parts like the offer's metadata. The peer answers with TT_FILE_OFFER (request_id echoed)
 * or TT_FILE_STATUS (transfer_id = request_id, result NOT_FOUND or REQUEST_REFUSED, with a
 * TT_FILE_REASON).
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtFileRequest extends SendCommand {
    /** Peer system id. (uint8_t) */
    public final int target_system;
    /** Peer component id. (uint8_t) */
    public final int target_component;
    /** Requester-chosen random nonce, never 0, new for every request. (uint32_t) */
    public final long request_id;
    /** Length of the whole name. [bytes] (uint8_t) */
    public final int name_length;
    /** Offset of this part in the name. [bytes] (uint8_t) */
    public final int name_offset;
    /** Part of the UTF-8 name. (uint8_t[80]) */
    public final byte[] name;

    public SendTtFileRequest(int target_system, int target_component, long request_id, int name_length, int name_offset, byte[] name) {
        super(DEFAULT_PRIORITY, 0, 0, 1.0);
        this.target_system = target_system;
        this.target_component = target_component;
        this.request_id = request_id;
        this.name_length = name_length;
        this.name_offset = name_offset;
        this.name = name;
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtFileRequest msg = new TtFileRequest();
        msg.target_system = this.target_system;
        msg.target_component = this.target_component;
        msg.request_id = this.request_id;
        msg.name_length = this.name_length;
        msg.name_offset = this.name_offset;
        msg.name = this.name;
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_FILE_REQUEST is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_FILE_REQUEST fails (error is usually a CommandException)
    }
}
