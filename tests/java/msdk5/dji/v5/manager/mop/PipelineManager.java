package dji.v5.manager.mop;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

import dji.sdk.keyvalue.value.mop.PipelineDeviceType;
import dji.sdk.keyvalue.value.mop.TransmissionControlType;
import dji.v5.common.error.IDJIError;
import dji.v5.manager.interfaces.IPipelineManager;

/**
 * Stand-in for MSDK v5's dji.v5.manager.mop.PipelineManager (5.3.0+), as DJI's sample
 * (SampleCode-V5 MopVM.kt) uses it: connectPipeline returns null or an IDJIError, the pipeline is
 * then in getPipelines(); disconnectPipeline removes it. A connect opens a TCP connection to
 * TTCTL_FAKE_PIPELINE (host:port, environment or system property ttctl.fake.pipeline).
 */
public class PipelineManager implements IPipelineManager {
    private static final PipelineManager INSTANCE = new PipelineManager();
    private final Map<Integer, Pipeline> pipelines = new ConcurrentHashMap<>();

    public static PipelineManager getInstance() {
        return INSTANCE;
    }

    @Override
    public Map<Integer, Pipeline> getPipelines() {
        return pipelines;
    }

    @Override
    public IDJIError connectPipeline(int pipelineId, PipelineDeviceType deviceType,
                                     TransmissionControlType transmissionControlType) {
        PipeStandIn.calls.incrementAndGet();
        if (PipeStandIn.failing()) {
            return PipeStandIn.failure();
        }
        if (pipelines.containsKey(pipelineId)) {
            return PipeStandIn.error("CONNECTED_ALREADY", "The pipeline " + pipelineId + " is connected already");
        }
        String where = PipeStandIn.setting("TTCTL_FAKE_PIPELINE", "ttctl.fake.pipeline");
        if (where == null) {
            return PipeStandIn.error("NOT_CONNECTED", "No onboard device (TTCTL_FAKE_PIPELINE unset)");
        }
        int colon = where.lastIndexOf(':');
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(where.substring(0, colon), Integer.parseInt(where.substring(colon + 1))), 1000);
            pipelines.put(pipelineId, new Pipeline(pipelineId, deviceType, transmissionControlType, s));
        } catch (IOException | RuntimeException e) {
            try {
                s.close();
            } catch (IOException ignored) {
                // never opened
            }
            return PipeStandIn.error("CONNECT_FAILED", "Pipeline connection failed: " + e.getMessage());
        }
        PipeStandIn.connects.incrementAndGet();
        return null;
    }

    @Override
    public IDJIError disconnectPipeline(int pipelineId, PipelineDeviceType deviceType,
                                        TransmissionControlType transmissionControlType) {
        PipeStandIn.calls.incrementAndGet();
        if (PipeStandIn.failing()) {
            return PipeStandIn.failure();
        }
        Pipeline p = pipelines.remove(pipelineId);
        if (p == null) {
            return PipeStandIn.error("NOT_CONNECTED", "The pipeline " + pipelineId + " is not connected");
        }
        p.close();
        return null;
    }
}
