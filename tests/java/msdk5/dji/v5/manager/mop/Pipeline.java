package dji.v5.manager.mop;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;

import dji.sdk.keyvalue.value.mop.PipelineDeviceType;
import dji.sdk.keyvalue.value.mop.TransmissionControlType;
import dji.v5.common.error.DJIPipeLineError;

/**
 * Stand-in for MSDK v5's dji.v5.manager.mop.Pipeline (IPipelineManager_Pipeline, 5.3.0+): a
 * connected pipeline. The stream is a TCP connection (see {@link PipeStandIn}): readData blocks
 * until bytes come (or {@value #READ_TIMEOUT_MS} ms pass: TIMEOUT, as DJI's sample expects),
 * writeData writes (at most 7 bytes a call with TTCTL_FAKE_PIPELINE_SHORT=1).
 */
public class Pipeline {
    static final int READ_TIMEOUT_MS = 500;

    private final int id;
    private final PipelineDeviceType deviceType;
    private final TransmissionControlType transmissionControlType;
    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;

    Pipeline(int id, PipelineDeviceType deviceType, TransmissionControlType transmissionControlType, Socket socket)
            throws IOException {
        this.id = id;
        this.deviceType = deviceType;
        this.transmissionControlType = transmissionControlType;
        this.socket = socket;
        socket.setSoTimeout(READ_TIMEOUT_MS);
        socket.setTcpNoDelay(true);
        socket.setSendBufferSize(16 * 1024); // an SDK's buffer, not a kernel's megabytes: a stalled pipeline blocks writeData
        this.in = socket.getInputStream();
        this.out = socket.getOutputStream();
    }

    public int getId() {
        return id;
    }

    public PipelineDeviceType getPipelineDeviceType() {
        return deviceType;
    }

    public TransmissionControlType getTransmissionControlType() {
        return transmissionControlType;
    }

    /** Send data to the PSDK device through the pipeline. */
    public DataResult writeData(byte[] data) {
        PipeStandIn.calls.incrementAndGet();
        if (PipeStandIn.failing()) {
            return new DataResult(-1, PipeStandIn.failure());
        }
        int n = PipeStandIn.shortWrites() ? Math.min(7, data.length) : data.length;
        try {
            out.write(data, 0, n);
            out.flush();
        } catch (IOException e) {
            return new DataResult(-1, PipeStandIn.error(DJIPipeLineError.CLOSING, "The pipeline is closing: " + e.getMessage()));
        }
        PipeStandIn.bytesWritten.addAndGet(n);
        return new DataResult(n, null);
    }

    /** Read data from the PSDK device through the pipeline. */
    public DataResult readData(byte[] data) {
        PipeStandIn.calls.incrementAndGet();
        if (PipeStandIn.failing()) {
            try {
                Thread.sleep(50); // a failing SDK still takes its time
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return new DataResult(-1, PipeStandIn.failure());
        }
        try {
            int n = in.read(data, 0, data.length);
            if (n < 0) {
                return new DataResult(-1, PipeStandIn.error(DJIPipeLineError.CLOSING, "The pipeline is closing: the onboard end closed it"));
            }
            PipeStandIn.bytesRead.addAndGet(n);
            return new DataResult(n, null);
        } catch (SocketTimeoutException e) {
            return new DataResult(-1, PipeStandIn.error(DJIPipeLineError.TIMEOUT, "Read timed out"));
        } catch (IOException e) {
            return new DataResult(-1, PipeStandIn.error(DJIPipeLineError.CLOSING, "The pipeline is closing: " + e.getMessage()));
        }
    }

    void close() {
        try {
            socket.close();
        } catch (IOException e) {
            // closed
        }
    }
}
