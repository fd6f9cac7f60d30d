/** Stand-in for dji.sdk.sdkmanager.DJISDKManager (DJI Mobile SDK v4). */
public final class DJISDKManager {
    private static final DJISDKManager INSTANCE = new DJISDKManager();

    public static DJISDKManager getInstance() {
        return INSTANCE;
    }

    public BaseProduct getProduct() {
        return new Aircraft();
    }
}
