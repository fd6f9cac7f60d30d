/** Stand-in for dji.sdk.flightcontroller.FlightController (DJI Mobile SDK v4): the two calls of DTT. */
public class FlightController {
    /** Data from the onboard computer (DJI's OnboardSDKDeviceDataCallback). */
    public interface OnboardSDKDeviceDataCallback {
        void onReceive(byte[] data);
    }

    public void sendDataToOnboardSDKDevice(byte[] data, CommonCallbacks.CompletionCallback callback) {
        callback.onResult(null);
    }

    public void setOnboardSDKDeviceDataCallback(OnboardSDKDeviceDataCallback callback) {
    }
}
