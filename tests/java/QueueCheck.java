import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.ReceiveTtCommandAck;
import ttctl.ttapi.commands.SendTtActionCommand;
import ttctl.ttapi.commands.SendTtVrPose;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.msg.TtCommandAck;
import ttctl.ttapi.runtime.CommandException;
import ttctl.ttapi.runtime.CommandQueue;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.UdpLink;

/**
 * End-to-end CommandQueue check over real loopback UDP (run by tests/test_gen_java.py against a
 * Python responder that answers TT_ACTION_COMMAND with TT_COMMAND_ACK, dropping the first two
 * tries of command_id 1 and the first try of every RETURN_HOME, never answering HOVER, and
 * answering SYNC_TIME with DENIED). Arguments: responder port, port of a peer that never
 * answers. Prints one "ok" line per check; exits 1 on the first failure.
 */
public final class QueueCheck {
    static final int SYSID = 255;
    static final int COMPID = 190;
    static final List<CompletableFuture<MavlinkMessage>> ALL = new ArrayList<>();
    static int checks;

    private QueueCheck() {
    }

    static void check(boolean condition, String what) {
        if (!condition) {
            System.out.println("FAIL " + what);
            System.out.flush();
            System.exit(1);
        }
    }

    static void ok(String what) {
        checks++;
        System.out.println("ok " + what);
        System.out.flush();
    }

    /** The generated skeleton, with callbacks that record what happened. */
    static final class Action extends SendTtActionCommand {
        final List<Integer> successes;
        final AtomicInteger failures = new AtomicInteger();
        final AtomicReference<Throwable> failure = new AtomicReference<>();

        Action(int targetSystem, int commandId, List<Integer> successes) {
            super(targetSystem, 1, commandId, TtAction.TT_ACTION_LAND, System.currentTimeMillis() * 1000L,
                    new float[4], new byte[48]);
            this.successes = successes;
        }

        @Override
        protected void onSuccess(MavlinkMessage reply) {
            successes.add(((TtCommandAck) reply).command_id);
        }

        @Override
        protected void onFailure(Throwable error) {
            failures.incrementAndGet();
            failure.set(error);
        }
    }

    static CompletableFuture<MavlinkMessage> submit(CommandQueue q, ttctl.ttapi.runtime.Command c) {
        CompletableFuture<MavlinkMessage> f = q.submit(c);
        ALL.add(f);
        return f;
    }

    static CommandException failureOf(CompletableFuture<MavlinkMessage> f, long seconds) throws Exception {
        try {
            f.get(seconds, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            check(e.getCause() instanceof CommandException, "cause " + e.getCause());
            return (CommandException) e.getCause();
        } catch (TimeoutException e) {
            check(false, "future did not complete within " + seconds + " s");
        }
        check(false, "expected a failure");
        return null;
    }

    static long millisSince(long t0) {
        return (System.nanoTime() - t0) / 1000000L;
    }

    /** Callbacks run on the queue's listener thread after the future completed: wait for them. */
    static boolean eventually(BooleanSupplier condition) throws InterruptedException {
        long t0 = System.nanoTime();
        while (!condition.getAsBoolean()) {
            if (millisSince(t0) > 2000) {
                return false;
            }
            Thread.sleep(2);
        }
        return true;
    }

    /** TT_ACTION_COMMAND with command_id and time_usec left to the queue. */
    static final class Plain extends SendTtActionCommand {
        final AtomicInteger failures = new AtomicInteger();
        final AtomicReference<Throwable> failure = new AtomicReference<>();

        Plain(int action) {
            super(1, 1, action, new float[4], new byte[48]);
        }

        @Override
        protected void onFailure(Throwable error) {
            failures.incrementAndGet();
            failure.set(error);
        }
    }

    public static void main(String[] args) throws Exception {
        int port = Integer.parseInt(args[0]);
        int silentPort = Integer.parseInt(args[1]);
        UdpLink link = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Ttapi.INSTANCE);
        CommandQueue q = new CommandQueue(link, SYSID, COMPID);
        link.addListener(q);
        link.start();
        q.start();
        List<Integer> done = Collections.synchronizedList(new ArrayList<Integer>());

        // 1. the responder drops the first two tries: success on the third, with backoff
        Action c1 = new Action(1, 1, done);
        c1.setTimeoutMillis(150).setBackoff(1.5).setMaxRetries(4);
        long t0 = System.nanoTime();
        MavlinkMessage reply = submit(q, c1).get(10, TimeUnit.SECONDS);
        long took = millisSince(t0);
        check(reply instanceof TtCommandAck && ((TtCommandAck) reply).command_id == 1, "reply " + reply);
        check(((TtCommandAck) reply).target_system == SYSID, "ack addressed to us");
        check(eventually(() -> done.equals(Arrays.asList(1))) && c1.failures.get() == 0, "onSuccess ran once: " + done);
        check(took >= 150 + 225 && took < 3000, "two timeouts (150 ms, then 225 ms) before the reply: " + took);
        ok("retries: succeeds on the third try after 150 + 225 ms timeouts; onSuccess ran (" + took + " ms)");

        // 2. a peer that never answers: TIMEOUT after 1 + maxRetries tries, onFailure ran
        UdpLink silentLink = UdpLink.open("127.0.0.1", 0, "127.0.0.1", silentPort, Ttapi.INSTANCE);
        CommandQueue silent = new CommandQueue(silentLink, SYSID, COMPID);
        silentLink.addListener(silent);
        silentLink.start();
        silent.start();
        List<Integer> silentDone = Collections.synchronizedList(new ArrayList<Integer>());
        Action c2 = new Action(1, 2, silentDone);
        c2.setTimeoutMillis(100).setBackoff(2.0).setMaxRetries(2);
        t0 = System.nanoTime();
        CommandException e2 = failureOf(submit(silent, c2), 10);
        took = millisSince(t0);
        check(e2.reason() == CommandException.Reason.TIMEOUT && e2.tries() == 3, "timeout after 3 tries: " + e2);
        check(eventually(() -> c2.failures.get() == 1) && c2.failure.get() == e2 && silentDone.isEmpty(),
                "onFailure ran once");
        check(took >= 100 + 200 + 400 && took < 5000, "waited 100 + 200 + 400 ms: " + took);
        ok("no answer: fails with TIMEOUT after 3 tries (" + took + " ms), onFailure ran, future exceptional");

        // 3. priorities: higher first, FIFO within a priority
        done.clear();
        q.pause();
        int[][] queued = {{10, 0}, {11, 5}, {12, 2}, {13, 5}, {14, 0}};
        List<CompletableFuture<MavlinkMessage>> batch = new ArrayList<>();
        for (int[] c : queued) {
            Action a = new Action(1, c[0], done);
            a.setPriority(c[1]).setTimeoutMillis(300).setMaxRetries(3);
            batch.add(submit(q, a));
        }
        check(q.pendingCount() == 5, "5 pending while paused");
        q.resume();
        for (CompletableFuture<MavlinkMessage> f : batch) {
            f.get(10, TimeUnit.SECONDS);
        }
        check(eventually(() -> done.size() == 5) && done.equals(Arrays.asList(11, 13, 12, 10, 14)), "priority order " + done);
        ok("priorities: sent and acknowledged in order 11, 13 (prio 5), 12 (prio 2), 10, 14 (prio 0)");

        // 4. a ReceiveCommand that gets nothing times out, and its future completes
        ReceiveTtCommandAck waitAck = new ReceiveTtCommandAck(200);
        t0 = System.nanoTime();
        CommandException e4 = failureOf(submit(q, waitAck), 5);
        took = millisSince(t0);
        check(e4.reason() == CommandException.Reason.TIMEOUT && took >= 200, "receive timeout " + e4 + " " + took);
        ok("receive: times out after 200 ms with TIMEOUT (" + took + " ms)");

        // 5. a ReceiveCommand on a second queue of the same link gets the ack of a command of the first
        CommandQueue watcher = new CommandQueue(link, SYSID, COMPID);
        link.addListener(watcher);
        watcher.start();
        CompletableFuture<MavlinkMessage> seen = submit(watcher, new ReceiveTtCommandAck(5000));
        long wait = System.nanoTime();
        while (watcher.pendingCount() > 0 && millisSince(wait) < 2000) {
            Thread.sleep(5);
        }
        Thread.sleep(50); // the watcher's command is in flight: waiting
        done.clear();
        Action c5 = new Action(1, 20, done);
        submit(q, c5).get(5, TimeUnit.SECONDS);
        MavlinkMessage got = seen.get(5, TimeUnit.SECONDS);
        check(got instanceof TtCommandAck && ((TtCommandAck) got).command_id == 20, "received " + got);
        ok("receive: a ReceiveCommand matches the TT_COMMAND_ACK addressed to us");

        // 6. a command that awaits no reply succeeds once sent
        float[] zero3 = new float[3];
        SendTtVrPose pose = new SendTtVrPose(1L, 1, 0, 0, 1, zero3, new float[] {0f, 0f, 0f, 1f}, zero3, zero3);
        check(submit(q, pose).get(5, TimeUnit.SECONDS) == null, "no reply expected: completes with null");
        ok("no reply expected: the command succeeds once sent");

        // 7. send failures complete the future (the original system's bug): bad value, closed link
        Action bad = new Action(300, 30, done); // target_system 300 does not fit uint8_t
        CommandException e7 = failureOf(submit(q, bad), 5);
        check(e7.reason() == CommandException.Reason.SEND_FAILED && e7.getCause() instanceof IllegalArgumentException
                && eventually(() -> bad.failures.get() == 1), "pack failure: " + e7);
        UdpLink closed = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Ttapi.INSTANCE);
        closed.close();
        CommandQueue dead = new CommandQueue(closed, SYSID, COMPID).start();
        CommandException e7b = failureOf(submit(dead, new Action(1, 31, done)), 5);
        check(e7b.reason() == CommandException.Reason.SEND_FAILED && e7b.getCause() instanceof java.io.IOException,
                "closed link: " + e7b);
        ok("send failures: packing and I/O errors fail the command at once with SEND_FAILED");

        // 8. closing completes the command in flight, the pending ones and later submissions
        CommandQueue stopping = new CommandQueue(silentLink, SYSID, COMPID);
        silentLink.addListener(stopping);
        stopping.start();
        Action inFlight = new Action(1, 40, silentDone);
        inFlight.setTimeoutMillis(5000).setMaxRetries(0);
        CompletableFuture<MavlinkMessage> f8a = submit(stopping, inFlight);
        CompletableFuture<MavlinkMessage> f8b = submit(stopping, new Action(1, 41, silentDone));
        CompletableFuture<MavlinkMessage> f8c = submit(stopping, new ReceiveTtCommandAck(5000));
        Thread.sleep(100);
        t0 = System.nanoTime();
        stopping.close();
        CompletableFuture<MavlinkMessage> f8d = submit(stopping, new Action(1, 42, silentDone));
        for (CompletableFuture<MavlinkMessage> f : Arrays.asList(f8a, f8b, f8c, f8d)) {
            CommandException e = failureOf(f, 5);
            check(e.reason() == CommandException.Reason.SHUTDOWN, "close: " + e);
        }
        check(millisSince(t0) < 2000, "close is prompt");
        check(stopping.awaitTermination(2, TimeUnit.SECONDS), "queue thread ended");
        ok("shutdown: close() completes in-flight, pending and later commands with SHUTDOWN");

        // 9. a cancelled future: the queue skips the command and still reports it
        q.pause();
        Action skipped = new Action(1, 50, done);
        CompletableFuture<MavlinkMessage> f9 = submit(q, skipped);
        f9.cancel(true);
        q.resume();
        Action after = new Action(1, 51, done);
        submit(q, after).get(5, TimeUnit.SECONDS);
        check(f9.isCancelled() && eventually(() -> skipped.failures.get() == 1), "cancelled command reported to onFailure");
        Action waiting = new Action(1, 52, silentDone);
        waiting.setTimeoutMillis(10000).setMaxRetries(0);
        CompletableFuture<MavlinkMessage> f9b = submit(silent, waiting);
        Thread.sleep(100);
        t0 = System.nanoTime();
        f9b.cancel(true);
        Action next = new Action(1, 53, silentDone);
        next.setTimeoutMillis(50).setMaxRetries(0);
        failureOf(submit(silent, next), 5);
        check(millisSince(t0) < 2000 && eventually(() -> waiting.failures.get() == 1)
                && ((CommandException) waiting.failure.get()).reason() == CommandException.Reason.CANCELLED,
                "cancelling the command in flight frees the queue at once");
        ok("cancel: a cancelled command is skipped (or stops waiting) and its onFailure told");

        // 10. ids and issue times chosen by the queue: distinct, non-zero, kept by retries
        Plain r1 = new Plain(TtAction.TT_ACTION_RETURN_HOME); // its first try is dropped: a retry
        Plain r2 = new Plain(TtAction.TT_ACTION_TAKE_OFF);
        r1.setTimeoutMillis(150).setMaxRetries(3);
        TtCommandAck a1 = (TtCommandAck) submit(q, r1).get(5, TimeUnit.SECONDS);
        TtCommandAck a2 = (TtCommandAck) submit(q, r2).get(5, TimeUnit.SECONDS);
        check(a1.command_id != 0 && a2.command_id != 0 && a1.command_id != a2.command_id,
                "queue-chosen ids " + a1.command_id + ", " + a2.command_id);
        check(a2.command_id == a1.command_id % 65535 + 1, "ids count up: " + a1.command_id + ", " + a2.command_id);
        System.out.println("IDS " + a1.command_id + " " + a2.command_id);
        ok("ids: the queue numbers commands left at 0 (" + a1.command_id + ", " + a2.command_id
                + ") and stamps their issue time; a retry repeats both");

        // 11. a DENIED ack is a refusal: the future fails with REFUSED and the ack, onFailure runs;
        // the ack came without the vehicle's words (the responder sends them only for a second
        // try, as if the first were lost), so the queue asked once more and has them now
        Plain denied = new Plain(TtAction.TT_ACTION_SYNC_TIME);
        CommandException e11 = failureOf(submit(q, denied), 5);
        String said = "refused: not now, " + new String(new char[20]).replace("\0", "a test ");
        check(e11.reason() == CommandException.Reason.REFUSED && e11.reply() instanceof TtCommandAck
                && !((TtCommandAck) e11.reply()).ok()
                && e11.getMessage().endsWith("refused: DENIED (" + said + ")")
                && e11.tries() == 2, "refused: " + e11 + " " + e11.reply());
        check(eventually(() -> denied.failures.get() == 1) && denied.failure.get() == e11, "onFailure of the refusal");
        ok("refused: a DENIED ack fails the future with REFUSED (" + e11.getMessage() + "), never a success");

        // 12. pre-emption: an urgent LAND is not held behind a HOVER that gets no answer
        Plain hover = new Plain(TtAction.TT_ACTION_HOVER);
        hover.setTimeoutMillis(400).setBackoff(1.0).setMaxRetries(2);
        CompletableFuture<MavlinkMessage> fh = submit(q, hover);
        Thread.sleep(50); // the HOVER is in flight
        Plain land = new Plain(TtAction.TT_ACTION_LAND);
        land.setPriority(ttctl.ttapi.runtime.Command.URGENT_PRIORITY);
        Plain later = new Plain(TtAction.TT_ACTION_TAKE_OFF); // default priority: waits for the HOVER
        t0 = System.nanoTime();
        CompletableFuture<MavlinkMessage> fl = submit(q, land);
        CompletableFuture<MavlinkMessage> fx = submit(q, later);
        TtCommandAck landAck = (TtCommandAck) fl.get(5, TimeUnit.SECONDS);
        long landMs = millisSince(t0);
        check(landAck.ok() && !fh.isDone() && !fx.isDone() && landMs < 300, "LAND acked in " + landMs + " ms, HOVER "
                + fh.isDone() + ", later " + fx.isDone());
        CommandException eh = failureOf(fh, 5);
        check(eh.reason() == CommandException.Reason.TIMEOUT && eh.tries() == 3, "hover " + eh);
        fx.get(5, TimeUnit.SECONDS);
        ok("pre-emption: an URGENT LAND behind an unanswered HOVER acked in " + landMs
                + " ms; a later command of the HOVER's priority waited for it");

        // every future completed
        for (CompletableFuture<MavlinkMessage> f : ALL) {
            check(f.isDone(), "a future never completed");
        }
        ok("every one of the " + ALL.size() + " futures completed");
        q.close();
        watcher.close();
        silent.close();
        dead.close();
        link.close();
        silentLink.close();
        System.out.println("DONE " + checks + " checks");
    }
}
