package dji.v5.manager.interfaces;

import dji.v5.common.callback.CommonCallbacks;
import dji.v5.manager.aircraft.payload.listener.PayloadDataListener;

/** Stand-in for MSDK v5's dji.v5.manager.interfaces.IPayloadManager (its data methods). */
public interface IPayloadManager {
    void addPayloadDataListener(PayloadDataListener listener);

    void removePayloadDataListener(PayloadDataListener listener);

    void clearAllPayloadDataListener();

    /** "Send command data to the payload. The maximum bandwidth of this channel is 3KBytes/s." */
    void sendDataToPayload(byte[] data, CommonCallbacks.CompletionCallback callback);
}
