import java.io.File;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import dji.sdk.keyvalue.value.mop.PipelineDeviceType;
import dji.sdk.keyvalue.value.mop.TransmissionControlType;
import dji.v5.common.callback.CommonCallbacks;
import dji.v5.common.error.DJIPipeLineError;
import dji.v5.common.error.IDJIError;
import dji.v5.manager.aircraft.payload.PayloadCenter;
import dji.v5.manager.aircraft.payload.PayloadIndexType;
import dji.v5.manager.interfaces.IPayloadManager;
import dji.v5.manager.mop.DataResult;
import dji.v5.manager.mop.PipeStandIn;
import dji.v5.manager.mop.Pipeline;
import dji.v5.manager.mop.PipelineManager;
import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.SendTtActionCommand;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.runtime.Link;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.PacketReceiver;
import ttctl.ttapi.runtime.PayloadLink;
import ttctl.ttapi.runtime.PipelineLink;
import ttctl.ttapi.runtime.Session;
import ttctl.ttapi.runtime.Signing;
import ttctl.ttapi.runtime.UdpLink;
import ttctl.ttapi.transfer.Transfer;
import ttctl.ttapi.transfer.TransferResult;

/**
 * The tablet of tests/test_java_pipeline.py: a Session on a low-speed link (UDP to udp=HOST:PORT,
 * standing in for PayloadLink or DjiLink) with a MOP pipeline wired to the stand-in MSDK v5
 * PipelineManager (tests/java/msdk5: TCP to TTCTL_FAKE_PIPELINE) as docs/dji/tablet-java.md wires
 * it. Arguments key=value; prints "EVENT ..." lines and one "RESULT k=v ..." line.
 *
 * run=e2e send=FILE fetch=NAME dir=DIR: waits for the pipeline, then a command, an upload and a
 * fetch; run=fail: (every SDK call fails) a command over the link, the SDK's words; run=flood
 * secs=S: the peer floods the pipeline with garbage; a command over the link meanwhile.
 */
public final class PipelineTablet {
    static final int PIPELINE_ID = 9745;
    static final List<String> STATE = new CopyOnWriteArrayList<>();

    /** An SDK result in ttctl's terms: DataResult's length and IDJIError's words. */
    static PipelineLink.Result result(int length, IDJIError e) {
        return e == null ? PipelineLink.Result.ok(length) : PipelineLink.Result.error(length, e.errorCode(), e.description());
    }

    /** The wiring, as docs/dji/tablet-java.md has it. */
    static PipelineLink pipeline(Signing signing) {
        PipelineManager mop = PipelineManager.getInstance();
        return new PipelineLink(new PipelineLink.Sdk() {
            private volatile Pipeline pipe;

            @Override
            public PipelineLink.Result connect() {
                IDJIError e = mop.connectPipeline(PIPELINE_ID, PipelineDeviceType.ONBOARD, TransmissionControlType.STABLE);
                pipe = e == null ? mop.getPipelines().get(PIPELINE_ID) : null;
                return e != null || pipe != null ? result(0, e) : PipelineLink.Result.error(-1, "NO_PIPELINE", "not in getPipelines()");
            }

            @Override
            public PipelineLink.Result read(byte[] buffer) {
                DataResult r = pipe.readData(buffer);
                IDJIError e = r.getError();
                if (e != null && DJIPipeLineError.TIMEOUT.equals(e.errorCode())) {
                    return PipelineLink.Result.ok(0); // nothing to read yet, as DJI's sample reads on
                }
                return result(r.getLength(), e);
            }

            @Override
            public PipelineLink.Result write(byte[] data) {
                DataResult r = pipe.writeData(data);
                return result(r.getLength(), r.getError());
            }

            @Override
            public PipelineLink.Result disconnect() {
                return result(0, mop.disconnectPipeline(PIPELINE_ID, PipelineDeviceType.ONBOARD, TransmissionControlType.STABLE));
            }
        }, Ttapi.INSTANCE, signing);
    }

    static int retries = -1; // the commands' (retries=N), or the runtime's default

    public static void main(String[] argv) throws Exception {
        Map<String, String> a = new HashMap<>();
        for (String s : argv) {
            int i = s.indexOf('=');
            a.put(s.substring(0, i), s.substring(i + 1));
        }
        String run = a.get("run");
        retries = a.containsKey("retries") ? Integer.parseInt(a.get("retries")) : -1;
        StringBuilder out = new StringBuilder("RESULT run=" + run);
        Signing signing = a.containsKey("key") ? new Signing(unhex(a.get("key")), 1, false) : null;
        Link low;
        if ("payload".equals(a.get("low"))) { // MSDK v5's payload data channel (the stand-in's UDP: -Dttctl.msdk.udp)
            IPayloadManager payload = PayloadCenter.getInstance().getPayloadManager().get(PayloadIndexType.EXTERNAL);
            PayloadLink link = new PayloadLink((packet, done) -> payload.sendDataToPayload(packet,
                    new CommonCallbacks.CompletionCallback() {
                        @Override
                        public void onSuccess() {
                            done.success();
                        }

                        @Override
                        public void onFailure(IDJIError error) {
                            done.failure(error.errorCode(), error.description());
                        }
                    }), new PacketReceiver(Ttapi.INSTANCE, signing));
            payload.addPayloadDataListener(link::onDataFromPayload);
            low = link;
        } else {
            String[] udp = a.get("udp").split(":");
            UdpLink link = new UdpLink(new DatagramSocket(new InetSocketAddress("127.0.0.1", 0)),
                    new InetSocketAddress(udp[0], Integer.parseInt(udp[1])), Ttapi.INSTANCE, signing);
            link.setMtu(Integer.parseInt(a.getOrDefault("mtu", "128")));
            low = link;
        }
        PipelineLink pipe = pipeline(signing);
        pipe.addStateListener((open, why) -> {
            STATE.add((open ? "open: " : "closed: ") + why);
            System.out.println("EVENT pipeline " + (open ? "open" : "closed") + ": " + why);
        });
        Session.Options options = new Session.Options();
        options.rate = low instanceof PayloadLink ? 0 : Double.parseDouble(a.getOrDefault("rate", "4000"));
        options.linkRate = low instanceof PayloadLink ? 3000 : 0;
        options.pipeline = pipe;
        options.signing = signing; // the pipeline's frames go under link id 1 ^ 0x80
        options.pipeRate = Double.parseDouble(a.getOrDefault("pipe_rate", "100000"));
        options.transfers = new ttctl.ttapi.transfer.TransferConfig();
        options.transfers.giveUpAfter = Double.parseDouble(a.getOrDefault("timeout", "30"));
        Session session = new Session(low, 255, 190, options).start();
        out.append(" mtu=").append(session.scheduler().mtu());
        long t0 = System.nanoTime();
        if ("e2e".equals(run)) {
            long waitOpen = Long.parseLong(a.getOrDefault("wait_open_ms", "15000")) * 1_000_000L;
            while (!pipe.isOpen() && System.nanoTime() - t0 < waitOpen) {
                Thread.sleep(20);
            }
            out.append(" opened=").append(pipe.isOpen());
            double ms = command(session, 20000, out);
            out.append(" command_ms=").append(Math.round(ms));
            List<Double> base = new ArrayList<>();
            for (int i = 0; i < 5; i++) {
                base.add(command(session, 20000, new StringBuilder()));
            }
            File f = a.containsKey("send") ? new File(a.get("send")) : null;
            Transfer up = f == null ? null : session.files().send(f, f.getName(), 1, 240, false, null);
            Transfer down = a.containsKey("fetch")
                    ? session.files().fetch(a.get("fetch"), new File(a.get("dir")), 1, 240, null) : null;
            List<Double> during = new ArrayList<>();
            while ((up != null && !up.future().isDone()) || (down != null && !down.future().isDone())) {
                if (during.size() < 200) {
                    during.add(command(session, 20000, new StringBuilder())); // commands while the files move
                }
                Thread.sleep(200);
            }
            TransferResult ru = up == null ? null : up.await(300, TimeUnit.SECONDS);
            TransferResult rd = down == null ? null : down.await(300, TimeUnit.SECONDS);
            out.append(" base_p95_ms=").append(Math.round(p95(base)));
            out.append(" during_p95_ms=").append(Math.round(p95(during))).append(" during_n=").append(during.size());
            out.append(" send_ok=").append(ru != null && ru.ok);
            out.append(" send_goodput=").append(ru == null ? -1 : Math.round(ru.goodput()));
            out.append(" fetch_goodput=").append(rd == null ? -1 : Math.round(rd.goodput()));
            out.append(" send_sha256=").append(f == null ? "none" : hex(f));
            if (ru != null && !ru.ok) {
                System.out.println("EVENT send failed: " + ru.message);
            }
            if (down != null) {
                File got = new File(a.get("dir"), a.get("fetch"));
                out.append(" fetch_ok=").append(rd != null && rd.ok);
                out.append(" fetch_sha256=").append(got.isFile() ? hex(got) : "none");
                if (rd != null && !rd.ok) {
                    System.out.println("EVENT fetch failed: " + rd.message);
                }
            }
            out.append(" command_after_ms=").append(Math.round(command(session, 20000, new StringBuilder())));
        } else if ("fail".equals(run)) {
            double ms = command(session, 20000, out);
            out.append(" command_ms=").append(Math.round(ms));
            Thread.sleep(Long.parseLong(a.getOrDefault("wait_ms", "4000")));
            out.append(" problem_has_words=").append(has(pipe.problem()));
            out.append(" told_state=").append(STATE.stream().anyMatch(PipelineTablet::has));
            out.append(" states=").append(STATE.size());
            out.append(" open=").append(pipe.isOpen());
            System.out.println("EVENT problem: " + pipe.problem());
        } else if ("split".equals(run)) {
            while ((pipe.connects() < 2 || pipe.framesIn() < 1) && System.nanoTime() - t0 < 15_000_000_000L) {
                Thread.sleep(20);
            }
            Thread.sleep(300);
            out.append(" discarded=").append(pipe.discardedAtClose());
        } else if ("flood".equals(run)) {
            while (!pipe.isOpen() && System.nanoTime() - t0 < 15_000_000_000L) {
                Thread.sleep(20);
            }
            out.append(" opened=").append(pipe.isOpen());
            long end = System.nanoTime() + (long) (Double.parseDouble(a.getOrDefault("secs", "5")) * 1e9);
            double worst = 0;
            while (System.nanoTime() < end) {
                worst = Math.max(worst, command(session, 20000, new StringBuilder()));
            }
            out.append(" worst_command_ms=").append(Math.round(worst));
            Runtime rt = Runtime.getRuntime();
            System.gc();
            Thread.sleep(300);
            System.gc();
            out.append(" heap_mb=").append((rt.totalMemory() - rt.freeMemory()) >> 20);
        }
        out.append(" pipe_connects=").append(pipe.connects());
        out.append(" pipe_bytes_out=").append(pipe.bytesOut());
        out.append(" pipe_bytes_in=").append(pipe.bytesIn());
        out.append(" pipe_frames_in=").append(pipe.framesIn());
        out.append(" pipe_short_writes=").append(pipe.shortWrites());
        out.append(" pipe_dropped=").append(pipe.droppedPackets());
        out.append(" sdk_calls=").append(PipeStandIn.calls.get());
        out.append(" sdk_connects=").append(PipeStandIn.connects.get());
        out.append(" low_bytes=").append(session.scheduler().bytes());
        out.append(" pipe_sched_bytes=").append(session.pipeScheduler().bytes());
        System.out.println(out);
        System.out.flush();
        long c0 = System.nanoTime();
        session.close();
        System.out.println("EVENT closed in " + Math.round((System.nanoTime() - c0) / 1e6) + " ms");
        System.exit(0);
    }

    /** Whether {@code s} carries the stand-in SDK's words. */
    static boolean has(String s) {
        return s != null && s.contains(PipeStandIn.WORDS) && s.contains(PipeStandIn.CODE);
    }

    static double command(Session s, long waitMs, StringBuilder out) throws Exception {
        long t0 = System.nanoTime();
        SendTtActionCommand c = new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4], new byte[48]);
        if (retries >= 0) { // the test's, on a busy machine: its processes wait for cores, not the link
            c.setMaxRetries(retries);
        }
        MavlinkMessage ack = s.submit(c).get(waitMs, TimeUnit.MILLISECONDS);
        out.append(" command_ack=").append(ack.name());
        return (System.nanoTime() - t0) / 1e6;
    }

    static double p95(List<Double> xs) {
        if (xs.isEmpty()) {
            return -1;
        }
        List<Double> s = new ArrayList<>(xs);
        Collections.sort(s);
        return s.get(Math.min(s.size() - 1, (int) Math.ceil(0.95 * s.size()) - 1));
    }

    static byte[] unhex(String s) {
        byte[] b = new byte[s.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }

    static String hex(File f) throws Exception {
        byte[] d = MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(f.toPath()));
        StringBuilder b = new StringBuilder();
        for (byte x : d) {
            b.append(String.format("%02x", x));
        }
        return b.toString();
    }
}
