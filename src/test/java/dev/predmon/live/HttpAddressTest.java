package dev.predmon.live;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class HttpAddressTest {

    @Test
    void aPortAloneIsLoopback() throws Exception {
        HttpAddress a = HttpAddress.parse("8080");
        assertEquals(new HttpAddress("127.0.0.1", 8080), a);
        assertTrue(a.loopback());
    }

    @Test
    void hostsAndIpv6InBrackets() throws Exception {
        assertEquals(new HttpAddress("0.0.0.0", 80), HttpAddress.parse("0.0.0.0:80"));
        assertFalse(HttpAddress.parse("0.0.0.0:80").loopback());
        assertEquals(new HttpAddress("::1", 9000), HttpAddress.parse("[::1]:9000"));
        assertTrue(HttpAddress.parse("[::1]:9000").loopback());
        assertTrue(HttpAddress.parse("localhost:0").loopback());
    }

    @Test
    void malformedAddressesSayWhatIsExpected() {
        for (String bad : new String[] {"", "http", ":80", "::1:80", "1.2.3.4:99999", "-1", "host:"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> HttpAddress.parse(bad), bad);
            assertFalse(e.getMessage().isBlank());
        }
    }
}
