// A skeleton written by ttctl gen from ttapi.xml: yours to edit; `ttctl gen` does not
// overwrite it (unless --force-skeletons).
package ttctl.ttapi.commands;

import ttctl.ttapi.msg.TtActionCommand;
import ttctl.ttapi.msg.TtCommandAck;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.MessageMatcher;
import ttctl.ttapi.runtime.SendCommand;

/**
 * Sends TT_ACTION_COMMAND: [sender: tablet] Ask the onboard computer to perform an action. Answered
 * by TT_COMMAND_ACK with the same command_id; a retry repeats command_id, so the action runs once.
 * <p>
 * Waits for TT_COMMAND_ACK with the same command_id addressed to us (target_system 0 or our system
 * id); retries with backoff when it does not come (see {@link SendCommand}).
 * <p>
 * The message is packed anew on every try from the values given to the constructor.
 */
public class SendTtActionCommand extends SendCommand {
    /** Receiver system id. (uint8_t) */
    public final int target_system;
    /** Receiver component id. (uint8_t) */
    public final int target_component;
    /**
     * Sender-chosen id, repeated on retries. (uint16_t) 0 (the default): the command queue's id for
     * this submission, the same on every retry.
     */
    public final int command_id;
    /** What to do. (uint8_t; enum {@link ttctl.ttapi.enums.TtAction}) */
    public final int action;
    /**
     * Sender's clock (UNIX epoch) when the command was issued. [us] (uint64_t) 0 (the default): the
     * time the command was submitted, the same on every retry.
     */
    public final long time_usec;
    /** Action parameters, see TT_ACTION. (float[4]) */
    public final float[] param;
    /** Action argument, e.g. the mission file of FLY_TRAJECTORY. (char[48]) */
    public final byte[] argument;

    /**
     * The values to send, command_id and time_usec chosen by the command queue (see the fields).
     */
    public SendTtActionCommand(int target_system, int target_component, int action, float[] param, byte[] argument) {
        this(target_system, target_component, 0, action, 0, param, argument);
    }

    /**
     * The values to send, packed anew on every try. Arrays are copied: changing yours afterwards
     * changes nothing sent.
     */
    public SendTtActionCommand(int target_system, int target_component, int command_id, int action, long time_usec, float[] param, byte[] argument) {
        super(DEFAULT_PRIORITY,  // its place in the command queue
              3,  // retries after the first try when no reply comes in time
              500,  // milliseconds the first try waits for the reply
              2.0);  // each retry waits this many times longer than the one before
        this.target_system = target_system;
        this.target_component = target_component;
        this.command_id = command_id;
        this.action = action;
        this.time_usec = time_usec;
        this.param = param == null ? null : param.clone();
        this.argument = argument == null ? null : argument.clone();
    }

    @Override
    protected MavlinkMessage createMessage(CommandContext ctx, int attempt) {
        TtActionCommand msg = new TtActionCommand();
        msg.target_system = this.target_system;
        msg.target_component = this.target_component;
        msg.command_id = this.command_id != 0 ? this.command_id : ctx.commandId();
        msg.action = this.action;
        msg.time_usec = this.time_usec != 0 ? this.time_usec : ctx.issuedUsec();
        msg.param = this.param == null ? null : this.param.clone();
        msg.argument = this.argument == null ? null : this.argument.clone();
        return msg;
    }

    @Override
    protected MessageMatcher expectedReply(final CommandContext ctx) {
        return MessageMatcher.of(TtCommandAck.MSG_ID, TtCommandAck.class,
            reply -> reply.command_id == (this.command_id != 0 ? this.command_id : ctx.commandId())
                && (reply.target_system == 0 || reply.target_system == ctx.sysId()));
    }

    @Override
    protected void onSuccess(MavlinkMessage reply) {
        // TODO: what to do once TT_ACTION_COMMAND is acknowledged
    }

    @Override
    protected void onFailure(Throwable error) {
        // TODO: what to do when TT_ACTION_COMMAND fails (error is usually a CommandException)
    }
}
