#!/usr/bin/env python3
"""Writes recorded runs with the independent writers, for predmon's tests on bags it never wrote.

Usage: write_runs.py IN_DIR OUT_DIR [FORM ...]

Every IN_DIR/**/NAME.messages.json (a list of {"topic", "type", "log_time" (ns), "fields"}, in recording order) is
written in each FORM (all four when none is given), its folders below IN_DIR kept:

  rosbags_sqlite3   OUT_DIR/rosbags_sqlite3/.../NAME/   rosbag2 folder by rosbags, sqlite3 storage
  rosbags_mcap      OUT_DIR/rosbags_mcap/.../NAME/      rosbag2 folder by rosbags, MCAP storage
  zstd              OUT_DIR/zstd/.../NAME.mcap          mcap-ros2-support, zstd chunks
  lz4               OUT_DIR/lz4/.../NAME.mcap           mcap-ros2-support, lz4 chunks

Fields a message leaves out get their type's default (zero, false, empty), as a ROS 2 publisher's message does.
The message definitions are the ROS 2 Jazzy ones rosbags bundles.
"""
import re
import sys
import json
from pathlib import Path

from mcap.writer import CompressionType
from mcap_ros2.writer import Writer as McapRos2Writer
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.typesys import Stores, get_typestore

sys.path.insert(0, str(Path(__file__).parent))
from write_bags import to_rosbags  # noqa: E402

FORMS = ['rosbags_sqlite3', 'rosbags_mcap', 'zstd', 'lz4']
ZEROS = {'bool': False, 'string': '', 'float32': 0.0, 'float64': 0.0}


def complete(ts, typename, value):
    """value with every field of typename, the missing ones at their defaults."""
    _, fields = ts.fielddefs[typename]
    out = {}
    for name, (kind, desc) in fields:
        v = value.get(name)
        if kind.name == 'BASE':
            out[name] = v if v is not None else ZEROS.get(desc[0], 0)
        elif kind.name == 'NAME':
            out[name] = complete(ts, desc, v or {})
        else:
            (ekind, edesc), length = desc
            if v is None:
                v = [ZEROS.get(edesc[0], 0) if ekind.name == 'BASE' else {}] * (length if kind.name == 'ARRAY' else 0)
            out[name] = [complete(ts, edesc, x) for x in v] if ekind.name == 'NAME' else list(v)
    return out


def write(ts, form, msgs, target):
    target.parent.mkdir(parents=True, exist_ok=True)
    if form.startswith('rosbags_'):
        plugin = StoragePlugin.SQLITE3 if form == 'rosbags_sqlite3' else StoragePlugin.MCAP
        with Writer(target, version=9, storage_plugin=plugin) as w:
            conns = {}
            for m in msgs:
                topic, typ = m['topic'], m['type']
                if topic not in conns:
                    conns[topic] = w.add_connection(topic, typ, typestore=ts)
                fields = complete(ts, typ, m['fields'])
                w.write(conns[topic], m['log_time'], ts.serialize_cdr(to_rosbags(ts, typ, fields), typ))
        return
    compression = CompressionType.ZSTD if form == 'zstd' else CompressionType.LZ4
    with open(target, 'wb') as f:
        w = McapRos2Writer(f, compression=compression, chunk_size=4096)
        schemas = {}
        for m in msgs:
            typ = m['type']
            if typ not in schemas:
                # rosbags writes ROS 1's 'time' for builtin_interfaces/Time, which mcap-ros2 does not take
                text = re.sub(r'^time(\[[^]]*\])? ', r'builtin_interfaces/Time\1 ', ts.generate_msgdef(typ)[0],
                              flags=re.M)
                schemas[typ] = w.register_msgdef(typ, text)
            w.write_message(m['topic'], schemas[typ], complete(ts, typ, m['fields']), log_time=m['log_time'],
                            publish_time=m['log_time'])
        w.finish()


def main(src, out, forms):
    ts = get_typestore(Stores.ROS2_JAZZY)
    files = sorted(src.rglob('*.messages.json'))
    if not files:
        sys.exit(f'no *.messages.json in {src}')
    for file in files:
        rel = file.relative_to(src)
        name = rel.name[:-len('.messages.json')]
        msgs = json.loads(file.read_text(encoding='utf-8'))
        for form in forms:
            folder = out / form / rel.parent
            write(ts, form, msgs, folder / (name if form.startswith('rosbags_') else name + '.mcap'))
    print(len(files) * len(forms))


if __name__ == '__main__':
    forms = sys.argv[3:] or FORMS
    unknown = [f for f in forms if f not in FORMS]
    if unknown:
        sys.exit(f'unknown form(s) {unknown}: expected some of {FORMS}')
    main(Path(sys.argv[1]), Path(sys.argv[2]), forms)
