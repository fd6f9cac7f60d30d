package dji.v5.manager.aircraft.payload;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import dji.v5.common.callback.CommonCallbacks;
import dji.v5.common.error.IDJIError;
import dji.v5.manager.aircraft.payload.listener.PayloadDataListener;
import dji.v5.manager.interfaces.IPayloadManager;

/**
 * Not a DJI class: the test's handle on the stand-in MSDK v5. The EXTERNAL payload manager sends
 * over UDP to {@code ttctl.msdk.udp} (host:port, a `ttctl link relay` or an onboard end) from a
 * socket of its own, and hands what comes back to the PayloadDataListeners on one SDK thread, as
 * DJI's documents describe the channel: a send is cut into packets of at most 128 bytes, the
 * channel carries at most 3 KB/s ({@code ttctl.msdk.rate}), and the completion of each send comes
 * on the SDK's thread when its bytes have left. {@code ttctl.msdk.mode}: {@code ok}; {@code
 * refuse} (every send completes with an IDJIError, the SDK's words); {@code throw} (every call
 * throws). It counts the longest time the app kept the SDK's thread in a callback.
 */
public final class StandIn {
    public static final int PACKET = 128;
    public static final String CODE = "NOT_CONNECTED_STANDIN";
    public static final String WORDS = "The aircraft is not connected (stand-in)";

    private static final StandIn ONE = new StandIn();

    final CopyOnWriteArrayList<PayloadDataListener> listeners = new CopyOnWriteArrayList<>();
    private final ScheduledExecutorService sdkThread = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "dji-sdk-callback");
        t.setDaemon(true);
        return t;
    });
    private final ExecutorService reader = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "dji-sdk-udp");
        t.setDaemon(true);
        return t;
    });
    private volatile String mode = System.getProperty("ttctl.msdk.mode", "ok");
    private final double rate = Double.parseDouble(System.getProperty("ttctl.msdk.rate", "3000"));
    private DatagramSocket socket;
    private InetSocketAddress to;
    private long channelFreeAt = System.nanoTime();
    public final AtomicLong sends = new AtomicLong();
    public final AtomicLong refused = new AtomicLong();
    public final AtomicLong packetsOut = new AtomicLong();
    public final AtomicLong packetsIn = new AtomicLong();
    public final AtomicLong callbacks = new AtomicLong();
    public final AtomicLong longestCallbackNanos = new AtomicLong();

    private final IPayloadManager manager = new IPayloadManager() {
        @Override
        public void addPayloadDataListener(PayloadDataListener listener) {
            check();
            listeners.addIfAbsent(listener);
        }

        @Override
        public void removePayloadDataListener(PayloadDataListener listener) {
            check();
            listeners.remove(listener);
        }

        @Override
        public void clearAllPayloadDataListener() {
            check();
            listeners.clear();
        }

        @Override
        public void sendDataToPayload(byte[] data, CommonCallbacks.CompletionCallback callback) {
            sends.incrementAndGet();
            check();
            send(data, callback);
        }
    };

    private StandIn() {
        String udp = System.getProperty("ttctl.msdk.udp");
        try {
            socket = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        } catch (SocketException e) {
            throw new IllegalStateException(e);
        }
        if (udp != null) {
            int c = udp.lastIndexOf(':');
            to = new InetSocketAddress(udp.substring(0, c), Integer.parseInt(udp.substring(c + 1)));
            reader.execute(this::read);
        }
    }

    public static StandIn get() {
        return ONE;
    }

    static IPayloadManager manager() {
        return ONE.manager;
    }

    public void setMode(String m) {
        mode = m;
    }

    private void check() {
        if ("throw".equals(mode)) {
            throw new IllegalStateException("stand-in MSDK: every call fails");
        }
    }

    private synchronized void send(byte[] data, CommonCallbacks.CompletionCallback cb) {
        if ("refuse".equals(mode) || to == null) {
            refused.incrementAndGet();
            sdkThread.execute(() -> timed(() -> cb.onFailure(error(CODE, WORDS))));
            return;
        }
        if (data == null || data.length == 0) {
            sdkThread.execute(() -> timed(() -> cb.onFailure(error("INVALID_PARAM_STANDIN", "No data (stand-in)"))));
            return;
        }
        long now = System.nanoTime();
        for (int at = 0; at < data.length; at += PACKET) { // "split into 128-byte packets"
            byte[] p = Arrays.copyOfRange(data, at, Math.min(data.length, at + PACKET));
            try {
                socket.send(new DatagramPacket(p, p.length, to));
                packetsOut.incrementAndGet();
            } catch (IOException e) {
                sdkThread.execute(() -> timed(() -> cb.onFailure(error("SEND_FAILED_STANDIN", e.toString()))));
                return;
            }
        }
        channelFreeAt = Math.max(now, channelFreeAt) + (long) (data.length * 1e9 / rate);
        sdkThread.schedule(() -> timed(cb::onSuccess), channelFreeAt - now, TimeUnit.NANOSECONDS);
    }

    private void read() {
        byte[] buf = new byte[2048];
        while (true) {
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            try {
                socket.receive(p);
            } catch (IOException e) {
                return;
            }
            packetsIn.incrementAndGet();
            byte[] data = Arrays.copyOf(p.getData(), p.getLength());
            sdkThread.execute(() -> deliver(data));
        }
    }

    /** Hands {@code data} to every listener on the SDK's thread (as the radio's data would come). */
    public void deliver(byte[] data) {
        for (PayloadDataListener l : listeners) {
            timed(() -> l.onDataFromPayloadUpdate(data));
        }
    }

    /**
     * A listener flood on the SDK's thread: {@code n} packets of random bytes (every 100th one
     * 64 KiB, the rest 128 bytes) as fast as the app's listener returns; returns the seconds it took.
     */
    public double flood(int n, long seed) throws Exception {
        Random r = new Random(seed);
        long t0 = System.nanoTime();
        sdkThread.submit(() -> {
            for (int i = 0; i < n; i++) {
                byte[] d = new byte[i % 100 == 99 ? 65536 : PACKET];
                r.nextBytes(d);
                deliver(d);
            }
        }).get(120, TimeUnit.SECONDS);
        return (System.nanoTime() - t0) / 1e9;
    }

    private void timed(Runnable r) {
        long t0 = System.nanoTime();
        try {
            r.run();
        } catch (RuntimeException e) {
            System.out.println("EVENT the app threw into the SDK's thread: " + e);
        }
        callbacks.incrementAndGet();
        longestCallbackNanos.accumulateAndGet(System.nanoTime() - t0, Math::max);
    }

    static IDJIError error(String code, String words) {
        return new IDJIError() {
            @Override
            public String errorCode() {
                return code;
            }

            @Override
            public String hint() {
                return "";
            }

            @Override
            public String description() {
                return words;
            }

            @Override
            public String toString() {
                return "ErrorImp{errorType='STANDIN', errorCode='" + code + "', description='" + words + "'}";
            }
        };
    }
}
