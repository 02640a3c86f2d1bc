package dev.predmon.rosbag;

import org.sqlite.SQLiteConfig;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * Reads a rosbag2 sqlite3 file ({@code .db3}, rosbag2_storage_sqlite3) of any schema version: {@code topics(id,
 * name, type, serialization_format, ...)} and {@code messages(id, topic_id, timestamp, data)}, with the message
 * definitions of {@code message_definitions(topic_type, encoding, encoded_message_definition, ...)} where the file
 * has that table (Iron and later; Humble's files have none, and predmon's bundled definitions stand in). Messages
 * are delivered ordered by timestamp, then id, as rosbag2 plays them.
 */
final class Db3Reader {

    private Db3Reader() {
    }

    /** Reads {@code file}; what cannot be read is one problem line, after the messages before it. */
    static void read(Path file, BagSink sink) {
        Topics topics = new Topics(file, sink);
        SQLiteConfig config = new SQLiteConfig();
        config.setReadOnly(true);
        String where = "the file";
        try (Connection c = config.createConnection("jdbc:sqlite:" + file.toAbsolutePath());
             Statement s = c.createStatement()) {
            Set<String> tables = names(s, "SELECT name FROM sqlite_master WHERE type = 'table'");
            for (String t : new String[] {"topics", "messages"}) {
                if (!tables.contains(t)) {
                    topics.problem(where, "expected the table '" + t + "' of a rosbag2 sqlite3 file, found the tables "
                            + tables);
                    return;
                }
            }
            Map<String, String[]> definitions = new HashMap<>();
            if (tables.contains("message_definitions")) {
                where = "the table message_definitions";
                try (ResultSet r = s.executeQuery("SELECT topic_type, encoding, encoded_message_definition "
                        + "FROM message_definitions")) {
                    while (r.next()) {
                        definitions.put(r.getString(1), new String[] {text(r.getString(2)), text(r.getString(3))});
                    }
                }
            }
            where = "the table topics";
            boolean formats = names(s, "SELECT name FROM pragma_table_info('topics')").contains("serialization_format");
            try (ResultSet r = s.executeQuery("SELECT id, name, type, "
                    + (formats ? "serialization_format" : "'cdr'") + " FROM topics")) {
                while (r.next()) {
                    String type = text(r.getString(3));
                    String[] d = definitions.getOrDefault(type, new String[] {"", ""});
                    topics.declare(r.getInt(1), text(r.getString(2)), type, text(r.getString(4)), d[0], d[1]);
                }
            }
            where = "the table messages";
            try (ResultSet r = s.executeQuery("SELECT id, topic_id, timestamp, data FROM messages "
                    + "ORDER BY timestamp, id")) {
                while (r.next()) {
                    where = "row id " + r.getLong(1) + " of the table messages";
                    byte[] data = r.getBytes(4);
                    if (data == null) {
                        data = new byte[0];
                    }
                    topics.message(r.getInt(2), r.getLong(3), data, 0, data.length, where);
                    where = "the row after id " + r.getLong(1) + " of the table messages";
                }
            }
        } catch (SQLException e) {
            topics.problem(where, "expected a rosbag2 sqlite3 database, SQLite says: " + oneLine(e.getMessage()));
        }
    }

    private static Set<String> names(Statement s, String query) throws SQLException {
        Set<String> out = new HashSet<>();
        try (ResultSet r = s.executeQuery(query)) {
            while (r.next()) {
                out.add(r.getString(1));
            }
        }
        return out;
    }

    private static String text(String s) {
        return s == null ? "" : s;
    }

    private static String oneLine(String s) {
        return s == null ? "(no message)" : s.replaceAll("\\s+", " ").trim();
    }
}
