// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileReason;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_FILE_REASON: [sender: any] Why a transfer or a request was refused or failed, in words
 * for people: sent just before each TT_FILE_STATUS that carries such a result (refused, failed, not
 * found, request refused), so the sender can say what the receiver knows.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtFileReason extends SendCommand {
    /** File sender's (or requester's) system id. (uint8_t) */
    public final int target_system;
    /** File sender's (or requester's) component id. (uint8_t) */
    public final int target_component;
    /** Transfer id from the offer (or request_id, for answers to a request). (uint32_t) */
    public final long transfer_id;
    /** The result the reason explains. (uint8_t; enum {@link ttctl.ttapi.enums.TtFileResult}) */
    public final int result;
    /** UTF-8 reason, NUL-terminated if shorter than 80 bytes. (char[80]) */
    public final byte[] text;

    public SendTtFileReason(int target_system, int target_component, long transfer_id, int result, byte[] text) {
        super(DEFAULT_PRIORITY, 0, 0, 1.0);
        this.target_system = target_system;
        this.target_component = target_component;
        this.transfer_id = transfer_id;
        this.result = result;
        this.text = text;
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtFileReason msg = new TtFileReason();
        msg.target_system = this.target_system;
        msg.target_component = this.target_component;
        msg.transfer_id = this.transfer_id;
        msg.result = this.result;
        msg.text = this.text;
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_FILE_REASON is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_FILE_REASON fails (error is usually a CommandException)
    }
}
