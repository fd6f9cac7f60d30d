/** Stand-in for dji.common.util.CommonCallbacks (DJI Mobile SDK v4). */
public final class CommonCallbacks {
    private CommonCallbacks() {
    }

    /** The completion of an SDK call: null on success, else the error. */
    public interface CompletionCallback {
        void onResult(DJIError error);
    }
}
