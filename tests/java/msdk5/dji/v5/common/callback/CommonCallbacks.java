package dji.v5.common.callback;

import dji.v5.common.error.IDJIError;

/** Stand-in for MSDK v5's dji.v5.common.callback.CommonCallbacks (the part ttctl uses). */
public class CommonCallbacks {
    /** "The callback does not carry any return message from an asynchronous operation." */
    public interface CompletionCallback {
        void onSuccess();

        void onFailure(IDJIError error);
    }
}
