package dji.v5.common.error;

/** Stand-in for MSDK v5's dji.v5.common.error.IDJIError ("Error code management class"). */
public interface IDJIError {
    String errorCode();

    String hint();

    String description();
}
