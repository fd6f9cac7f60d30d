// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtLog;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_LOG: [sender: any] A log or status line. Text longer than 80 bytes continues in further
 * messages with the same id and increasing chunk_seq; a chunk with a NUL in text is the last.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtLog extends SendCommand {
    /** Sender's time since boot. [ms] (uint32_t) */
    public final long time_boot_ms;
    /** Line id, the same for every chunk of one line (0: single chunk). (uint16_t) */
    public final int id;
    /** Severity. (uint8_t; enum {@link ttctl.ttapi.enums.MavSeverity}) */
    public final int severity;
    /** Chunk number within the line, from 0. (uint8_t) */
    public final int chunk_seq;
    /** UTF-8 text, NUL-terminated if shorter than 80 bytes. (char[80]) */
    public final byte[] text;

    /**
     * The values to send, packed anew on every try. Arrays are copied: changing yours afterwards
     * changes nothing sent.
     */
    public SendTtLog(long time_boot_ms, int id, int severity, int chunk_seq, byte[] text) {
        super(DEFAULT_PRIORITY,  // its place in the command queue
              0,  // no retries: it awaits no reply, so it succeeds once sent
              0,  // no reply timeout, for the same reason
              1.0);  // no backoff between retries, there are none
        this.time_boot_ms = time_boot_ms;
        this.id = id;
        this.severity = severity;
        this.chunk_seq = chunk_seq;
        this.text = text == null ? null : text.clone();
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtLog msg = new TtLog();
        msg.time_boot_ms = this.time_boot_ms;
        msg.id = this.id;
        msg.severity = this.severity;
        msg.chunk_seq = this.chunk_seq;
        msg.text = this.text == null ? null : this.text.clone();
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_LOG is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_LOG fails (error is usually a CommandException)
    }
}
