package dev.predmon.rosbag;

import dev.predmon.rosbag.MsgDefinitions.DefinitionException;

import java.io.Closeable;
import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Writes a rosbag2 sqlite3 file ({@code .db3}) with the tables rosbag2 writes: schema version 4 (Iron and later:
 * with {@code message_definitions}), or, with {@code humble}, schema version 3 without message definitions, as
 * Humble's recorder leaves them. The file is written under a hidden temporary name beside {@code file} and moved into
 * place by {@link #close}: it is complete or not there.
 */
public final class Db3Writer implements Closeable {

    private final Path file;
    private final Path temp;
    private final boolean humble;
    private final Connection db;
    private final PreparedStatement insert;
    private final List<CdrCodec> codecs = new ArrayList<>();
    private final List<String> defined = new ArrayList<>();
    private boolean closed;

    /**
     * Starts a new {@code .db3} file.
     *
     * @throws FileAlreadyExistsException if {@code file} exists: it is never overwritten
     */
    public Db3Writer(Path file, boolean humble) throws IOException {
        if (Files.exists(file)) {
            throw new FileAlreadyExistsException(file.toString());
        }
        this.file = file;
        this.humble = humble;
        Path dir = file.toAbsolutePath().getParent();
        this.temp = dir.resolve("." + file.getFileName() + ".writing");
        Files.deleteIfExists(temp);
        try {
            db = DriverManager.getConnection("jdbc:sqlite:" + temp);
            db.setAutoCommit(false);
            try (Statement s = db.createStatement()) {
                String tables = String.format("""
            CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);
            CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, metadata TEXT NOT NULL);
            CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,
              serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL%s);
            %s
            CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL,
              data BLOB NOT NULL);
            CREATE INDEX timestamp_idx ON messages (timestamp ASC);
            """, humble ? "" : ", type_description_hash TEXT NOT NULL",
                        humble ? "" : "CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT "
                                + "NULL, encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL, "
                                + "type_description_hash TEXT NOT NULL);");
                for (String sql : tables.split(";", -1)) {
                    if (!sql.isBlank()) {
                        s.execute(sql);
                    }
                }
                s.execute("INSERT INTO schema(schema_version, ros_distro) VALUES (" + (humble ? 3 : 4) + ", '"
                        + (humble ? "humble" : "jazzy") + "')");
            }
            insert = db.prepareStatement("INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)");
        } catch (SQLException e) {
            Files.deleteIfExists(temp);
            throw new IOException(file + ": cannot write a sqlite3 file: " + e.getMessage(), e);
        }
    }

    /** Declares a topic of a type predmon bundles. */
    public int topic(String name, String type) throws IOException {
        return topic(name, type, BundledTypes.text(type));
    }

    /**
     * Declares a topic and returns its id; its definition goes to {@code message_definitions} (not with
     * {@code humble}).
     *
     * @throws IllegalArgumentException if the definition cannot be parsed
     */
    public int topic(String name, String type, String definition) throws IOException {
        try {
            Map<String, MsgDefinitions.Type> own = MsgDefinitions.parse(type, definition);
            codecs.add(CdrCodec.compile(type, own::get));
        } catch (DefinitionException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        int id = codecs.size();
        try (PreparedStatement p = db.prepareStatement("INSERT INTO topics VALUES (?, ?, ?, 'cdr', ''"
                + (humble ? ")" : ", '')"))) {
            p.setInt(1, id);
            p.setString(2, name);
            p.setString(3, type);
            p.executeUpdate();
            if (!humble && !defined.contains(type)) {
                defined.add(type);
                try (PreparedStatement d = db.prepareStatement("INSERT INTO message_definitions (topic_type, "
                        + "encoding, encoded_message_definition, type_description_hash) VALUES (?, 'ros2msg', ?, '')")) {
                    d.setString(1, type);
                    d.setString(2, definition);
                    d.executeUpdate();
                }
            }
        } catch (SQLException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        }
        return id;
    }

    /** Writes one message of {@code topic} encoded as CDR from {@code fields} (see {@link McapWriter#write}). */
    public void write(int topic, long timestampNanos, Map<String, ?> fields) throws IOException {
        if (topic < 1 || topic > codecs.size()) {
            throw new IllegalArgumentException("no topic " + topic + " (declared: 1.." + codecs.size() + ")");
        }
        write(topic, timestampNanos, codecs.get(topic - 1).encode(fields));
    }

    /** Writes one message of {@code topic} whose CDR bytes are {@code cdr}. */
    public void write(int topic, long timestampNanos, byte[] cdr) throws IOException {
        try {
            insert.setInt(1, topic);
            insert.setLong(2, timestampNanos);
            insert.setBytes(3, cdr);
            insert.executeUpdate();
        } catch (SQLException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        }
    }

    /** Commits, closes and moves the file into place. */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            insert.close();
            db.commit();
            db.close();
            Files.move(temp, file, StandardCopyOption.ATOMIC_MOVE);
        } catch (SQLException | IOException e) {
            Files.deleteIfExists(temp);
            throw new IOException(file + ": not written: " + e.getMessage(), e);
        }
    }
}
