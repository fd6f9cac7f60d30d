/** Stand-in for dji.common.error.DJIError (DJI Mobile SDK v4). */
public class DJIError {
    public String getDescription() {
        return "The product is not connected";
    }
}
