package dji.sdk.keyvalue.value.mop;

/** Stand-in for MSDK v5's dji.sdk.keyvalue.value.mop.PipelineDeviceType ("The device type of pipeline", 5.3.0+). */
public enum PipelineDeviceType {
    /** Onboard type. */
    ONBOARD,
    /** Payload type. */
    PAYLOAD
}
