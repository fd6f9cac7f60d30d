// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtFileStatus;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_FILE_STATUS: [sender: any] The receiver's view of a transfer: sent on accepting or
 * refusing an offer, while data flows (regularly, when new gaps appear, and when data stops
 * coming), and on completion. Bytes below received_contiguous have all arrived; in [region_start,
 * received_end) everything arrived except the listed missing ranges. When there are more gaps than
 * fit, several statuses describe successive regions. A sender takes a status for its own only if
 * both transfer_id and meta_check match its offer.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtFileStatus extends SendCommand {
    /** File sender's system id. (uint8_t) */
    public final int target_system;
    /** File sender's component id. (uint8_t) */
    public final int target_component;
    /** Transfer id from the offer (or request_id, for answers to a request). (uint32_t) */
    public final long transfer_id;
    /** State of the transfer. (uint8_t; enum {@link ttctl.ttapi.enums.TtFileResult}) */
    public final int result;
    /** All bytes before this offset have arrived. [bytes] (uint32_t) */
    public final long received_contiguous;
    /**
     * Start of the region this status describes (received_contiguous in the first status of a
     * burst). [bytes] (uint32_t)
     */
    public final long region_start;
    /** End of the region this status describes. [bytes] (uint32_t) */
    public final long received_end;
    /**
     * Offset of the latest data frame received (with hold_ms, lets the sender measure the
     * round-trip time). [bytes] (uint32_t)
     */
    public final long last_offset;
    /** Time between the arrival of that frame and this status, at most 65535. [ms] (uint16_t) */
    public final int hold_ms;
    /** Number of missing ranges listed in ranges. (uint8_t) */
    public final int range_count;
    /**
     * The first 4 bytes, little-endian, of the SHA-256 of the offer's whole metadata blob (the
     * file's SHA-256 then its name), once the receiver has all of it; 0 before (and in answers to a
     * request). It binds the status, COMPLETE above all, to that file under that name. (uint32_t)
     */
    public final long meta_check;
    /**
     * Missing byte ranges, ascending, as start, end (exclusive) pairs. An extension so that it
     * comes last on the wire: unused pairs are zero and truncated away, and a status with few gaps
     * is short. [bytes] (uint32_t[14]; extension)
     */
    public final long[] ranges;

    public SendTtFileStatus(int target_system, int target_component, long transfer_id, int result, long received_contiguous, long region_start, long received_end, long last_offset, int hold_ms, int range_count, long meta_check, long[] ranges) {
        super(DEFAULT_PRIORITY, 0, 0, 1.0);
        this.target_system = target_system;
        this.target_component = target_component;
        this.transfer_id = transfer_id;
        this.result = result;
        this.received_contiguous = received_contiguous;
        this.region_start = region_start;
        this.received_end = received_end;
        this.last_offset = last_offset;
        this.hold_ms = hold_ms;
        this.range_count = range_count;
        this.meta_check = meta_check;
        this.ranges = ranges;
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtFileStatus msg = new TtFileStatus();
        msg.target_system = this.target_system;
        msg.target_component = this.target_component;
        msg.transfer_id = this.transfer_id;
        msg.result = this.result;
        msg.received_contiguous = this.received_contiguous;
        msg.region_start = this.region_start;
        msg.received_end = this.received_end;
        msg.last_offset = this.last_offset;
        msg.hold_ms = this.hold_ms;
        msg.range_count = this.range_count;
        msg.meta_check = this.meta_check;
        msg.ranges = this.ranges;
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_FILE_STATUS is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_FILE_STATUS fails (error is usually a CommandException)
    }
}
