import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

import ttctl.ttapi.msg.TtActionCommand;
import ttctl.ttapi.msg.TtFileDataWide;
import ttctl.ttapi.runtime.Link;
import ttctl.ttapi.runtime.LinkScheduler;

/**
 * LinkScheduler without a network: packets of at most 100 bytes; 267-byte frames continue in
 * the next packets; a control frame queued while one is being cut goes in a packet of its own
 * between the pieces; bulk sources take turns; the rate cap holds. With a signer: every frame is
 * signed as it is placed, in the order frames go on the air, and nothing is slipped between a
 * long frame's pieces. With a control frame due at a known time (a command's retry): every bulk
 * packet sent before it has left the radio by then, and the link is not left idle for it.
 * Prints "ok ..." lines and DONE, or "FAIL ..." and exits 1.
 */
public final class SchedulerCheck {
    static void check(boolean ok, String what) {
        if (!ok) {
            System.out.println("FAIL " + what);
            System.exit(1);
        }
    }

    public static void main(String[] args) throws Exception {
        final List<byte[]> packets = Collections.synchronizedList(new ArrayList<byte[]>());
        final CountDownLatch gate = new CountDownLatch(1);
        final AtomicInteger sentCount = new AtomicInteger();
        Link link = new Link() {
            @Override
            public void send(byte[] packet) {
                packets.add(packet);
                sentCount.incrementAndGet();
            }

            @Override
            public boolean awaitReady(long timeoutNanos) throws InterruptedException {
                return gate.await(timeoutNanos, TimeUnit.NANOSECONDS); // held until the frames are queued
            }

            @Override
            public void close() {
            }
        };
        LinkScheduler s = new LinkScheduler(link, 100, 5000).start();
        final List<byte[]> wide = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            byte[] data = new byte[247];
            Arrays.fill(data, (byte) (i + 1));
            wide.add(new TtFileDataWide(7, 247L * i, data).pack(i, 255, 190));
        }
        final AtomicInteger pulledA = new AtomicInteger();
        final AtomicInteger pulledB = new AtomicInteger();
        s.addSource(space -> pulledA.get() < 2 ? wide.get(pulledA.getAndIncrement()) : null);
        s.addSource(space -> pulledB.get() < 2 ? wide.get(2 + pulledB.getAndIncrement()) : null);
        byte[] cmd = new TtActionCommand(1, 240, 9, 1, 0, new float[4], new byte[48]).pack(0, 255, 190);
        long t0 = System.nanoTime();
        gate.countDown();
        // queue the command while the first wide frame is being cut into packets
        while (sentCount.get() < 1) {
            Thread.sleep(1);
        }
        s.sendControl(cmd);
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        int need = (4 * wide.get(0).length + cmd.length + 99) / 100 + 1;
        while (System.nanoTime() < end && !(pulledA.get() == 2 && pulledB.get() == 2 && s.queued() == 0
                && total(packets) >= 4 * wide.get(0).length + cmd.length)) {
            Thread.sleep(5);
        }
        double secs = (System.nanoTime() - t0) / 1e9;
        List<byte[]> got = new ArrayList<>(packets);
        for (byte[] p : got) {
            check(p.length > 0 && p.length <= 100, "a packet of " + p.length + " bytes");
        }
        System.out.println("ok packets of at most 100 bytes: " + got.size() + " (about " + need + ")");
        int at = -1;
        for (int i = 0; i < got.size(); i++) {
            if (Arrays.equals(got.get(i), cmd)) {
                at = i;
            }
        }
        check(at >= 1 && at <= 2, "the command in a packet of its own right after the packet on the air, at " + at);
        System.out.println("ok the command went in a packet of its own between the pieces, packet " + at);
        ByteArrayOutputStream rest = new ByteArrayOutputStream();
        for (int i = 0; i < got.size(); i++) {
            if (i != at) {
                rest.write(got.get(i));
            }
        }
        ByteArrayOutputStream expect = new ByteArrayOutputStream();
        for (int i : new int[] {0, 2, 1, 3}) { // the sources take turns
            expect.write(wide.get(i));
        }
        check(Arrays.equals(rest.toByteArray(), expect.toByteArray()), "the wide frames continue back to back, in turn");
        System.out.println("ok long frames continue in the next packets, sources take turns");
        double floor = (total(got) - 100) / 5000.0;
        check(secs >= floor * 0.9, "paced: " + total(got) + " bytes in " + secs + " s at 5000 B/s");
        System.out.println("ok the rate cap holds");
        s.close();
        boolean refused = false;
        try {
            s.sendControl(cmd);
        } catch (IllegalStateException e) {
            refused = true;
        }
        check(refused, "a closed scheduler refuses frames");
        signed();
        due();
        System.out.println("DONE");
    }

    /** A signer that appends 13 bytes (the first: its call number) and sets the signed flag. */
    static void signed() throws Exception {
        final List<byte[]> packets = Collections.synchronizedList(new ArrayList<byte[]>());
        final CountDownLatch gate = new CountDownLatch(1);
        Link link = new Link() {
            @Override
            public void send(byte[] packet) {
                packets.add(packet);
            }

            @Override
            public boolean awaitReady(long timeoutNanos) throws InterruptedException {
                return gate.await(timeoutNanos, TimeUnit.NANOSECONDS);
            }

            @Override
            public void close() {
            }
        };
        final AtomicInteger calls = new AtomicInteger();
        LinkScheduler s = new LinkScheduler(link, 100, 20000).setSigner(f -> {
            byte[] out = Arrays.copyOf(f, f.length + 13);
            out[2] |= 1;
            out[f.length] = (byte) calls.getAndIncrement();
            return out;
        }).start();
        final List<byte[]> wide = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            byte[] data = new byte[247];
            Arrays.fill(data, (byte) (i + 1));
            wide.add(new TtFileDataWide(7, 247L * i, data).pack(i, 255, 190));
        }
        final AtomicInteger pulled = new AtomicInteger();
        s.addSource(space -> pulled.get() < 3 ? wide.get(pulled.getAndIncrement()) : null);
        byte[] telemetry = new TtActionCommand(1, 240, 8, 1, 0, new float[4], new byte[48]).pack(1, 255, 190);
        byte[] cmd = new TtActionCommand(1, 240, 9, 1, 0, new float[4], new byte[48]).pack(0, 255, 190);
        gate.countDown();
        while (packets.isEmpty()) {
            Thread.sleep(1);
        }
        s.sendTelemetry(telemetry); // queued before the command, placed after it: signed after it
        s.sendControl(cmd);
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        int want = 3 * (wide.get(0).length + 13) + 2 * (cmd.length + 13);
        while (System.nanoTime() < end && total(packets) < want) {
            Thread.sleep(5);
        }
        s.close();
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        for (byte[] p : new ArrayList<>(packets)) {
            check(p.length > 0 && p.length <= 100, "a signed packet of " + p.length + " bytes");
            all.write(p);
        }
        byte[] b = all.toByteArray();
        check(b.length == want, "signed frames: " + b.length + " bytes, not " + want);
        int o = 0;
        int frames = 0;
        while (o < b.length) { // back to back: nothing slipped between a long frame's pieces
            check((b[o] & 0xFF) == 0xFD && (b[o + 2] & 1) == 1, "a signed frame at byte " + o);
            int len = 12 + (b[o + 1] & 0xFF);
            check((b[o + len] & 0xFF) == frames, "frame " + frames + " on the air was signed " + b[o + len]);
            o += len + 13;
            frames++;
        }
        check(frames == 5, frames + " signed frames, not 5");
        System.out.println("ok signed as placed, in the order on the air, nothing slipped between pieces");
    }

    /** Bulk before a control frame due at a known time: packets that end by then (at 500 B/s). */
    static void due() throws Exception {
        final double rate = 500;
        final List<long[]> sent = Collections.synchronizedList(new ArrayList<long[]>()); // {at, bytes, control}
        Link link = new Link() {
            @Override
            public void send(byte[] packet) {
                sent.add(new long[] {System.nanoTime(), packet.length, (packet[0] & 0xFF) == 0xFD ? 1 : 0});
            }

            @Override
            public void close() {
            }
        };
        LinkScheduler s = new LinkScheduler(link, 100, rate).start();
        final AtomicLong due = new AtomicLong(Long.MAX_VALUE);
        s.addControlDue(due::get);
        s.addSource(space -> new byte[90]); // a ground station's uplink, say: always a 90-byte frame
        byte[] cmd = new TtActionCommand(1, 240, 9, 1, 0, new float[4], new byte[48]).pack(0, 255, 190);
        Thread.sleep(300);
        long t0 = System.nanoTime();
        List<Long> dues = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            long at = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(250 + 37 * i);
            dues.add(at);
            due.set(at);
            while (System.nanoTime() - at < 0) {
                LockSupport.parkNanos(at - System.nanoTime());
            }
            s.sendControl(cmd);
            due.set(Long.MAX_VALUE);
            Thread.sleep(100);
        }
        long t1 = System.nanoTime();
        s.close();
        List<long[]> got = new ArrayList<>(sent);
        long slack = TimeUnit.MILLISECONDS.toNanos(30); // a thread preempted between building and sending
        int controls = 0;
        long bulk = 0;
        for (long[] p : got) {
            if (p[2] == 1) {
                controls++;
                continue;
            }
            if (p[0] - t0 >= 0 && t1 - p[0] >= 0) {
                bulk += p[1];
            }
            long ends = p[0] + (long) (p[1] * 1e9 / rate);
            for (long at : dues) {
                check(!(p[0] - at < 0 && ends - (at + slack) > 0), "a " + p[1] + "-byte bulk packet sent "
                        + (at - p[0]) / 1000000 + " ms before a due control frame is still on the radio then");
            }
        }
        check(controls == 6, controls + " control packets, not 6");
        double secs = (t1 - t0) / 1e9;
        check(bulk + 6 * cmd.length >= 0.8 * rate * secs, "the link was left idle: " + bulk + " bulk bytes in " + secs + " s");
        System.out.println("ok bulk packets leave the radio before a due control frame");
    }

    static int total(List<byte[]> ps) {
        int n = 0;
        synchronized (ps) {
            for (byte[] p : ps) {
                n += p.length;
            }
        }
        return n;
    }
}
