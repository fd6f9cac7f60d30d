package dji.v5.manager.aircraft.payload;

import java.util.Collections;
import java.util.EnumMap;
import java.util.Map;

import dji.v5.manager.interfaces.IPayloadCenter;
import dji.v5.manager.interfaces.IPayloadManager;

/**
 * Stand-in for MSDK v5's PayloadCenter: one payload at EXTERNAL (the E-Port), whose data goes over
 * UDP (see {@link StandIn}).
 */
public class PayloadCenter implements IPayloadCenter {
    private static final PayloadCenter INSTANCE = new PayloadCenter();

    public static PayloadCenter getInstance() {
        return INSTANCE;
    }

    @Override
    public Map<PayloadIndexType, IPayloadManager> getPayloadManager() {
        Map<PayloadIndexType, IPayloadManager> m = new EnumMap<>(PayloadIndexType.class);
        m.put(PayloadIndexType.EXTERNAL, StandIn.manager());
        return Collections.unmodifiableMap(m);
    }
}
