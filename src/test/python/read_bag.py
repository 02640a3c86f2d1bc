#!/usr/bin/env python3
"""Reads a bag with the Python readers and prints its messages as JSON, for predmon's writer round-trip test.

Usage: read_bag.py FILE.mcap|FOLDER   (an MCAP file through mcap-ros2-support's decoder; a rosbag2 folder
through rosbags)
"""
import dataclasses
import json
import math
import sys
from pathlib import Path

import numpy as np


TYPESTORE = None


def plain(v):
    if isinstance(v, np.ndarray):
        return [plain(x) for x in v.tolist()]
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    if isinstance(v, (np.generic,)):
        return v.item()
    if isinstance(v, float) and math.isnan(v):
        return v
    if isinstance(v, (bytes, bytearray)):
        return list(v)
    if TYPESTORE is not None and hasattr(v, '__msgtype__'):
        return {n: plain(getattr(v, n)) for n, _ in TYPESTORE.fielddefs[v.__msgtype__][1]}
    if dataclasses.is_dataclass(v):
        return {f.name: plain(getattr(v, f.name)) for f in dataclasses.fields(v)}
    if hasattr(v, '__slots__'):
        return {n: plain(getattr(v, n)) for n in v.__slots__}
    return v


def main(path):
    out = []
    if path.is_file():
        from mcap.reader import make_reader
        from mcap_ros2.decoder import DecoderFactory
        with open(path, 'rb') as f:
            for schema, channel, message, decoded in make_reader(f, decoder_factories=[DecoderFactory()]) \
                    .iter_decoded_messages():
                out.append({'topic': channel.topic, 'type': schema.name, 'log_time': message.log_time,
                            'fields': plain(decoded)})
    else:
        from rosbags.rosbag2 import Reader
        from rosbags.typesys import Stores, get_typestore
        global TYPESTORE
        ts = TYPESTORE = get_typestore(Stores.ROS2_JAZZY)
        with Reader(path) as r:
            from rosbags.typesys import get_types_from_msg
            for c in r.connections:
                if c.msgdef.data:
                    ts.register(get_types_from_msg(c.msgdef.data, c.msgtype))
            for c, t, data in r.messages():
                out.append({'topic': c.topic, 'type': c.msgtype, 'log_time': t,
                            'fields': plain(ts.deserialize_cdr(data, c.msgtype))})
    json.dump(out, sys.stdout, ensure_ascii=False)


if __name__ == '__main__':
    main(Path(sys.argv[1]))
