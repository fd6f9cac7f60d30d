/** Stand-in for dji.sdk.base.BaseProduct (DJI Mobile SDK v4). */
public class BaseProduct {
}
