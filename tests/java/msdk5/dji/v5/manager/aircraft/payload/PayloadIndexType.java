package dji.v5.manager.aircraft.payload;

/**
 * Stand-in for MSDK v5's PayloadIndexType. EXTERNAL: "On the M300 RTK, this location is the OSDK
 * extension location. On the M350 RTK, this location is the E-PORT location."
 */
public enum PayloadIndexType {
    LEFT_OR_MAIN(0), RIGHT(1), UP(2), EXTERNAL(3);

    private final int value;

    PayloadIndexType(int value) {
        this.value = value;
    }

    public int value() {
        return value;
    }

    public static PayloadIndexType find(int value) {
        for (PayloadIndexType t : values()) {
            if (t.value == value) {
                return t;
            }
        }
        return null; // the stand-in's choice: DJI's own is not documented
    }
}
