package dji.v5.manager.aircraft.payload.listener;

/** Stand-in for MSDK v5's PayloadDataListener: "Listener of payload data. Supported since MSDK 5.2.0". */
public interface PayloadDataListener {
    void onDataFromPayloadUpdate(byte[] data);
}
