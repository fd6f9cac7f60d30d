// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtVrController;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_VR_CONTROLLER: [sender: tablet] Controller input, sent when OpenVR's packet number
 * changes. Axes follow the Joy layout of ROS Vive nodes: trigger, pad_x, pad_y.
 * <p>
 * Succeeds once sent: the message awaits no reply.
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtVrController extends SendCommand {
    /** Time of the sample (UNIX epoch). [us] (uint64_t) */
    public final long time_usec;
    /** OpenVR unPacketNum of this state. (uint32_t) */
    public final long packet_num;
    /** OpenVR device index. (uint8_t) */
    public final int index;
    /** Controller hand. (uint8_t; enum {@link ttctl.ttapi.enums.TtVrRole}) */
    public final int role;
    /** Trigger, 0..1. (float) */
    public final float trigger;
    /** Trackpad x, -1..1. (float) */
    public final float pad_x;
    /** Trackpad y, -1..1. (float) */
    public final float pad_y;
    /** Buttons held. (uint16_t; enum {@link ttctl.ttapi.enums.TtVrButtons}) */
    public final int buttons;

    /** The values to send, packed anew on every try. */
    public SendTtVrController(long time_usec, long packet_num, int index, int role, float trigger, float pad_x, float pad_y, int buttons) {
        super(DEFAULT_PRIORITY,  // its place in the command queue
              0,  // no retries: it awaits no reply, so it succeeds once sent
              0,  // no reply timeout, for the same reason
              1.0);  // no backoff between retries, there are none
        this.time_usec = time_usec;
        this.packet_num = packet_num;
        this.index = index;
        this.role = role;
        this.trigger = trigger;
        this.pad_x = pad_x;
        this.pad_y = pad_y;
        this.buttons = buttons;
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtVrController msg = new TtVrController();
        msg.time_usec = this.time_usec;
        msg.packet_num = this.packet_num;
        msg.index = this.index;
        msg.role = this.role;
        msg.trigger = this.trigger;
        msg.pad_x = this.pad_x;
        msg.pad_y = this.pad_y;
        msg.buttons = this.buttons;
        return msg;
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_VR_CONTROLLER is sent
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_VR_CONTROLLER fails (error is usually a CommandException)
    }
}
