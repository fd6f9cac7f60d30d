package dji.sdk.keyvalue.value.mop;

/** Stand-in for MSDK v5's dji.sdk.keyvalue.value.mop.TransmissionControlType (5.3.0+). */
public enum TransmissionControlType {
    /** Packets are transmitted in the order they were sent, similar to TCP. */
    STABLE,
    /** Packets can be corrupted or lost in transit, similar to UDP. */
    UNRELIABLE
}
