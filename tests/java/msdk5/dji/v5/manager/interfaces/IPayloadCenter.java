package dji.v5.manager.interfaces;

import java.util.Map;

import dji.v5.manager.aircraft.payload.PayloadIndexType;

/** Stand-in for MSDK v5's dji.v5.manager.interfaces.IPayloadCenter. */
public interface IPayloadCenter {
    Map<PayloadIndexType, IPayloadManager> getPayloadManager();
}
