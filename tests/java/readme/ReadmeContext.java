import java.io.File;
import java.util.function.Consumer;

import ttctl.ttapi.msg.Heartbeat;
import ttctl.ttapi.runtime.Dispatcher;
import ttctl.ttapi.runtime.Link;
import ttctl.ttapi.runtime.Session;
import ttctl.ttapi.transfer.Transfer;

/**
 * What the README's Java snippets take from the app around them (tests/test_java_session.py
 * pastes each snippet into a method of a subclass and compiles it with javac -Xlint:all
 * -Werror): an Android activity's getFilesDir(), a link, a folder, a transfer listener...
 * The DJI Mobile SDK's classes the snippets name are stand-ins with the SDK v4 signatures
 * (FlightController, Aircraft, DJISDKManager, DJIError, CommonCallbacks, Log), in this folder.
 */
public abstract class ReadmeContext {
    protected Link link;
    protected Session session;
    protected File dir = new File(".");
    protected Transfer.Listener listener;
    protected Dispatcher dispatcher = new Dispatcher();
    protected byte[] frame = new byte[12];
    protected byte[] packet = new byte[100];
    protected Heartbeat heartbeat = new Heartbeat();
    protected int seq;
    protected Consumer<byte[]> djiSend = p -> { };

    protected File getFilesDir() {
        return new File(".");
    }

    public abstract void run() throws Exception;
}
