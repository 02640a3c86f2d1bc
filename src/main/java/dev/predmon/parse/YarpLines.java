package dev.predmon.parse;

import java.util.regex.Pattern;

/**
 * YARP's own lines about the monitor's port: what YARP prints of the monitor's port and its connections when the
 * monitor starts, such as {@code [INFO] |yarp.os.Port| Port /monitor active at tcp://10.0.0.2:10032/} and
 * {@code [INFO] |yarp.os.impl.PortCoreInputUnit| Receiving input from /tick/monitor to /monitor using tcp}, with
 * colour codes or without, YARP 3's {@code |yarp.os.Port|/monitor|} form and YARP 2's {@code yarp: Port ...}. A monitor
 * started before the robot prints these and no record until the robot's first message: a log that holds only them
 * is a monitor log still waiting for its first record. YARP's lines of another program's ports ({@code Port /tool1
 * active}) are not: that program's log is no monitor log.
 */
final class YarpLines {

    /** A log component of YARP's own ({@code |yarp.os.Port|}), or YARP 2's {@code yarp:} prefix. */
    private static final Pattern YARP = Pattern.compile("(?:^|[\\s\\]])\\|yarp\\.[A-Za-z0-9_.]+\\||^\\s*yarp: ");

    private YarpLines() {
    }

    /** Whether {@code line} is one of YARP's own lines about the monitor's port. */
    static boolean is(String line) {
        return line.contains("yarp") && line.contains("monitor")
                && YARP.matcher(ConsoleLayout.withoutColours(line)).find();
    }
}
