package dji.v5.manager.mop;

import dji.v5.common.error.IDJIError;

/**
 * Stand-in for MSDK v5's dji.v5.manager.mop.DataResult (IPipelineManager_DataResult): the
 * length read or written, and the error (null when the read or write succeeded).
 */
public class DataResult {
    private final int length;
    private final IDJIError error;

    public DataResult() {
        this(-1, null);
    }

    DataResult(int length, IDJIError error) {
        this.length = length;
        this.error = error;
    }

    /** The length of data read or written by the pipeline. */
    public int getLength() {
        return length;
    }

    /** Null if the read or write succeeded, otherwise the error. */
    public IDJIError getError() {
        return error;
    }

    @Override
    public String toString() {
        return "DataResult{length=" + length + ", error=" + (error == null ? "null" : error.errorCode()) + "}";
    }
}
