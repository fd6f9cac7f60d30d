import java.io.File;
import java.nio.file.Files;
import java.security.MessageDigest;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import dji.v5.common.callback.CommonCallbacks;
import dji.v5.common.error.IDJIError;
import dji.v5.manager.aircraft.payload.PayloadCenter;
import dji.v5.manager.aircraft.payload.PayloadIndexType;
import dji.v5.manager.aircraft.payload.StandIn;
import dji.v5.manager.interfaces.IPayloadManager;
import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.SendTtActionCommand;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.PacketReceiver;
import ttctl.ttapi.runtime.PayloadLink;
import ttctl.ttapi.runtime.Session;
import ttctl.ttapi.transfer.Transfer;
import ttctl.ttapi.transfer.TransferResult;

/**
 * The tablet of tests/test_java_payload.py: the generated Java runtime wired to the MSDK v5
 * payload data channel exactly as docs/dji/tablet-java.md wires it (PayloadLink, a Session), on
 * the stand-in MSDK v5 (tests/java/msdk5: UDP to -Dttctl.msdk.udp, 128-byte packets, 3 KB/s,
 * completions on the SDK's thread). Arguments key=value; prints "EVENT ..." lines and one
 * "RESULT k=v ..." line.
 *
 * run=e2e send=FILE fetch=NAME dir=DIR: an upload, a fetch and a command, against an onboard end;
 * run=refuse: every send refused with the SDK's words; run=throw: every SDK call throws after the
 * wiring; run=flood n=N: the SDK's thread floods the listener.
 */
public final class PayloadTablet {
    static final List<String> STATE = new CopyOnWriteArrayList<>();

    public static void main(String[] argv) throws Exception {
        Map<String, String> a = new HashMap<>();
        for (String s : argv) {
            int i = s.indexOf('=');
            a.put(s.substring(0, i), s.substring(i + 1));
        }
        String run = a.get("run");
        StringBuilder out = new StringBuilder("RESULT run=" + run);

        // -- the wiring, as docs/dji/tablet-java.md has it --------------------------------------
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
                }), new PacketReceiver(Ttapi.INSTANCE));
        payload.addPayloadDataListener(link::onDataFromPayload);
        link.setStateListener((trouble, why) -> {
            STATE.add(why);
            System.out.println("EVENT link " + (trouble ? "trouble" : "ok") + ": " + why);
        });
        Session.Options options = new Session.Options();
        options.linkRate = 3000;
        options.transfers = new ttctl.ttapi.transfer.TransferConfig();
        options.transfers.giveUpAfter = Double.parseDouble(a.getOrDefault("timeout", "30"));
        Session session = new Session(link, 255, 190, options).start();
        // ------------------------------------------------------------------------------------------
        StandIn sdk = StandIn.get();
        out.append(" mtu=").append(session.scheduler().mtu());
        if ("e2e".equals(run)) {
            double ms = command(session, 20000, out);
            out.append(" command_ms=").append(Math.round(ms));
            File f = new File(a.get("send"));
            Transfer up = session.files().send(f, f.getName(), 1, 240, false, null);
            Transfer down = session.files().fetch(a.get("fetch"), new File(a.get("dir")), 1, 240, null);
            TransferResult ru = up.await(180, TimeUnit.SECONDS);
            TransferResult rd = down.await(180, TimeUnit.SECONDS);
            out.append(" send_ok=").append(ru != null && ru.ok).append(" fetch_ok=").append(rd != null && rd.ok);
            File got = new File(a.get("dir"), a.get("fetch"));
            out.append(" send_sha256=").append(hex(f)).append(" fetch_sha256=").append(got.isFile() ? hex(got) : "none");
            if (ru != null && !ru.ok) {
                System.out.println("EVENT send failed: " + ru.message);
            }
            if (rd != null && !rd.ok) {
                System.out.println("EVENT fetch failed: " + rd.message);
            }
        } else if ("refuse".equals(run) || "throw".equals(run)) {
            sdk.setMode(run);
            long t0 = System.nanoTime();
            String why = failure(session, 60000);
            out.append(" failed_in_s=").append(Math.round((System.nanoTime() - t0) / 1e8) / 10.0);
            System.out.println("EVENT the command failed: " + why);
            long sends0 = sdk.sends.get();
            Thread.sleep(3000);
            out.append(" sends_in_3s=").append(sdk.sends.get() - sends0);
            out.append(" problem_has_words=").append(has(link.problem()));
            out.append(" reason_has_words=").append(has(why));
            out.append(" told_state=").append(STATE.stream().anyMatch(PayloadTablet::has));
            out.append(" refusing=").append(link.isRefusing());
            System.out.println("EVENT problem: " + link.problem());
            sdk.setMode("ok");
        } else if ("flood".equals(run)) {
            int n = Integer.parseInt(a.getOrDefault("n", "200000"));
            double secs = sdk.flood(n, 5);
            Runtime rt = Runtime.getRuntime();
            System.gc();
            Thread.sleep(500);
            System.gc();
            out.append(" flood_s=").append(Math.round(secs * 100) / 100.0);
            out.append(" heap_mb=").append((rt.totalMemory() - rt.freeMemory()) >> 20);
            out.append(" dropped=").append(link.droppedReceived());
            out.append(" parsed=").append(link.received());
        }
        out.append(" sdk_sends=").append(sdk.sends.get());
        out.append(" sdk_packets_out=").append(sdk.packetsOut.get());
        out.append(" longest_sdk_callback_ms=").append(Math.round(sdk.longestCallbackNanos.get() / 1e5) / 10.0);
        out.append(" sdk_callbacks=").append(sdk.callbacks.get());
        System.out.println(out);
        System.out.flush();
        session.close();
        System.exit(0);
    }

    /** Whether {@code s} carries the stand-in SDK's words. */
    static boolean has(String s) {
        return s != null && (s.contains(StandIn.WORDS) && s.contains(StandIn.CODE) || s.contains("every call fails"));
    }

    static SendTtActionCommand action() {
        return new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4], new byte[48]);
    }

    static double command(Session s, long waitMs, StringBuilder out) throws Exception {
        long t0 = System.nanoTime();
        MavlinkMessage ack = s.submit(action()).get(waitMs, TimeUnit.MILLISECONDS);
        out.append(" command_ack=").append(ack.name());
        return (System.nanoTime() - t0) / 1e6;
    }

    static String failure(Session s, long waitMs) throws Exception {
        try {
            s.submit(action()).get(waitMs, TimeUnit.MILLISECONDS);
            return "no failure";
        } catch (ExecutionException e) {
            return String.valueOf(e.getCause().getMessage());
        }
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
