package jacabot.experiments.link;

import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorInfoCodec;
import jacabot.robot.link.Uplink;
import java.io.IOException;
import java.io.ObjectOutputStream;

/** Hand-written uplink frames for the link's guard tests (readings the real writer would never send). */
public final class RawFrames {
    private RawFrames() {
    }

    /** Writes one batch frame of {@code readings} at control step {@code step} (40 ms steps). */
    public static void batch(ObjectOutputStream out, long step, SensorInfo... readings) throws IOException {
        out.writeByte(Uplink.BATCH);
        out.writeLong(step);
        out.writeLong(40 * step);
        out.writeLong(0);
        out.writeInt(readings.length);
        for (SensorInfo r : readings) {
            SensorInfoCodec.write(out, r);
        }
        out.flush();
    }
}
