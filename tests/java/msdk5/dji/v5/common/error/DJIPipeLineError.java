package dji.v5.common.error;

/**
 * Stand-in for MSDK v5's dji.v5.common.error.DJIPipeLineError: the two codes DJI's sample app
 * (SampleCode-V5 MopVM.kt, PipelineAdapter.java) compares {@code IDJIError.errorCode()} with.
 */
public final class DJIPipeLineError {
    public static final String TIMEOUT = "TIMEOUT";
    public static final String CLOSING = "CLOSING";

    private DJIPipeLineError() {
    }
}
