package dev.predmon.live;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;

/**
 * Where the live view listens, as given to {@code --http [HOST:]PORT}: {@code 8080} is {@code 127.0.0.1:8080}
 * (loopback, the default: only this machine can see the page); {@code 0.0.0.0:8080}, {@code [::1]:8080} or a host
 * name choose an interface; port 0 takes any free port.
 *
 * @param host the host as written (an IPv6 literal without brackets), {@code 127.0.0.1} when none was
 * @param port 0..65535
 */
public record HttpAddress(String host, int port) {

    public HttpAddress {
        if (port < 0 || port > 65_535) {
            throw new IllegalArgumentException("port must be 0..65535, got " + port);
        }
        if (host.isEmpty()) {
            throw new IllegalArgumentException("empty host");
        }
    }

    /** Parses {@code [HOST:]PORT}; an IPv6 host is written in brackets. */
    public static HttpAddress parse(String text) {
        String s = text.strip();
        int colon = s.lastIndexOf(':');
        String host = "127.0.0.1";
        String port = s;
        if (colon >= 0) {
            host = s.substring(0, colon);
            port = s.substring(colon + 1);
            if (host.startsWith("[") && host.endsWith("]")) {
                host = host.substring(1, host.length() - 1);
            } else if (host.contains(":")) {
                throw new IllegalArgumentException("'" + text + "': write an IPv6 host in brackets, e.g. [::1]:8080");
            }
            if (host.isEmpty()) {
                throw new IllegalArgumentException("'" + text + "': no host before ':' (write just the port for loopback)");
            }
        }
        try {
            return new HttpAddress(host, Integer.parseInt(port));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "': expected [HOST:]PORT, e.g. 8080 or 0.0.0.0:8080");
        }
    }

    /** The socket address to bind (resolves a host name). */
    public InetSocketAddress socketAddress() throws UnknownHostException {
        return new InetSocketAddress(InetAddress.getByName(host), port);
    }

    /** Whether only this machine can connect: a loopback address. */
    public boolean loopback() throws UnknownHostException {
        return InetAddress.getByName(host).isLoopbackAddress();
    }
}
