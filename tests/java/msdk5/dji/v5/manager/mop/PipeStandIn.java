package dji.v5.manager.mop;

import java.util.concurrent.atomic.AtomicLong;

import dji.v5.common.error.IDJIError;

/**
 * Not a DJI class: the stand-in pipelines' settings and counters. TTCTL_FAKE_PIPELINE=HOST:PORT
 * (or -Dttctl.fake.pipeline): where connectPipeline connects over TCP;
 * TTCTL_FAKE_PIPELINE_SHORT=1: every writeData takes at most 7 bytes;
 * TTCTL_FAKE_PIPELINE_FAIL=1: every call returns the error {@link #CODE}, {@link #WORDS}.
 */
public final class PipeStandIn {
    public static final String CODE = "PIPELINE_UNAVAILABLE_STANDIN";
    public static final String WORDS = "The pipeline service is unavailable (stand-in)";
    public static final AtomicLong calls = new AtomicLong();
    public static final AtomicLong connects = new AtomicLong();
    public static final AtomicLong bytesWritten = new AtomicLong();
    public static final AtomicLong bytesRead = new AtomicLong();

    private PipeStandIn() {
    }

    static String setting(String env, String property) {
        String v = System.getProperty(property);
        return v != null ? v : System.getenv(env);
    }

    static boolean failing() {
        return "1".equals(setting("TTCTL_FAKE_PIPELINE_FAIL", "ttctl.fake.pipeline.fail"));
    }

    static boolean shortWrites() {
        return "1".equals(setting("TTCTL_FAKE_PIPELINE_SHORT", "ttctl.fake.pipeline.short"));
    }

    static IDJIError failure() {
        return error(CODE, WORDS);
    }

    static IDJIError error(final String code, final String words) {
        return new IDJIError() {
            @Override
            public String errorCode() {
                return code;
            }

            @Override
            public String hint() {
                return words;
            }

            @Override
            public String description() {
                return words;
            }

            @Override
            public String toString() {
                return "ErrorImp{errorCode='" + code + "', description='" + words + "'}";
            }
        };
    }
}
