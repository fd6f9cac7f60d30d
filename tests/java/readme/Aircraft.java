/** Stand-in for dji.sdk.products.Aircraft (DJI Mobile SDK v4). */
public class Aircraft extends BaseProduct {
    public FlightController getFlightController() {
        return new FlightController();
    }
}
