package dji.v5.manager.interfaces;

import java.util.Map;

import dji.sdk.keyvalue.value.mop.PipelineDeviceType;
import dji.sdk.keyvalue.value.mop.TransmissionControlType;
import dji.v5.common.error.IDJIError;
import dji.v5.manager.mop.Pipeline;

/** Stand-in for MSDK v5's dji.v5.manager.interfaces.IPipelineManager (5.3.0+): the calls ttctl uses. */
public interface IPipelineManager {
    /** The connected pipelines, by pipeline id; a disconnected one is removed. */
    Map<Integer, Pipeline> getPipelines();

    /** Connects pipeline {@code pipelineId}; null on success, else the error. */
    IDJIError connectPipeline(int pipelineId, PipelineDeviceType deviceType, TransmissionControlType transmissionControlType);

    IDJIError disconnectPipeline(int pipelineId, PipelineDeviceType deviceType, TransmissionControlType transmissionControlType);
}
