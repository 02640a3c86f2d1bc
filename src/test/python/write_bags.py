#!/usr/bin/env python3
"""Writes the same ROS 2 messages with two independent writers, for predmon's reader tests.

Usage: write_bags.py OUTDIR

OUTDIR/rosbags_sqlite3/   rosbag2 folder written by rosbags (sqlite3 storage, schema 4, with definitions)
OUTDIR/rosbags_mcap/      rosbag2 folder written by rosbags (MCAP storage, uncompressed chunks)
OUTDIR/zstd.mcap          written by mcap-ros2-support, zstd chunks
OUTDIR/lz4.mcap           written by mcap-ros2-support, lz4 chunks
OUTDIR/expected.json      the messages written, in order: topic, type, log time (ns) and field values

Every float is exactly representable as a float32, so that the expected values need no rounding. NaN is written
as the JSON token NaN, a uint64 as a JSON integer.
"""
import json
import math
import re
import sys
from pathlib import Path

import numpy as np
from mcap.writer import CompressionType
from mcap_ros2.writer import Writer as McapRos2Writer
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

NAV2_LOG = """builtin_interfaces/Time timestamp
BehaviorTreeStatusChange[] event_log
"""
NAV2_CHANGE = """builtin_interfaces/Time timestamp
string node_name
uint16 uid
string previous_status
string current_status
"""
EVERYTHING = """# every kind of field the decoder must handle
int32 CONSTANT=7
string GREETING="hi # not a comment"
int8 a_int8
uint8 a_uint8
int16 a_int16
uint16 a_uint16
int32 a_int32
uint32 a_uint32
int64 a_int64
uint64 a_uint64
float32 a_float32
float64 a_float64
bool a_bool
byte a_byte
char a_char
string a_string
string<=10 bounded_string
float64[3] fixed_doubles
int32[<=4] bounded_ints
uint8[] some_bytes
string[] strings
bool[2] flags
builtin_interfaces/Time[2] times
std_msgs/Header header
"""


def time(sec, nanosec):
    return {'sec': sec, 'nanosec': nanosec}


def messages():
    """(topic, type, log_time_ns, fields) in writing order."""
    t0 = 1_700_000_000_000_000_000
    uuid_a = list(range(16))
    uuid_b = [255 - i for i in range(16)]
    out = []

    def battery(i, pct, cells):
        return {'header': {'stamp': time(1_700_000_000 + i, 500_000_000), 'frame_id': 'base_link'},
                'voltage': 24.25, 'temperature': 31.5, 'current': -1.5, 'charge': 10.0, 'capacity': 20.0,
                'design_capacity': 22.0, 'percentage': pct, 'power_supply_status': 2, 'power_supply_health': 1,
                'power_supply_technology': 2, 'present': True, 'cell_voltage': cells,
                'cell_temperature': [], 'location': 'slot0', 'serial_number': ''}

    out.append(('/battery_state', 'sensor_msgs/msg/BatteryState', t0, battery(0, 0.75, [3.5, 3.25])))
    out.append(('/navigate_to_pose/_action/status', 'action_msgs/msg/GoalStatusArray', t0 + 1, {'status_list': [
        {'goal_info': {'goal_id': {'uuid': uuid_a}, 'stamp': time(1_700_000_000, 0)}, 'status': 2},
        {'goal_info': {'goal_id': {'uuid': uuid_b}, 'stamp': time(1_700_000_001, 7)}, 'status': 6}]}))
    out.append(('/rosout', 'rcl_interfaces/msg/Log', t0 + 2, {
        'stamp': time(1_700_000_002, 1), 'level': 40, 'name': 'bt_navigator', 'msg': 'Goal failed: ünreachable',
        'file': 'bt_navigator.cpp', 'function': 'onGoal', 'line': 123}))
    out.append(('/diagnostics', 'diagnostic_msgs/msg/DiagnosticArray', t0 + 3, {
        'header': {'stamp': time(1_700_000_003, 0), 'frame_id': ''},
        'status': [{'level': 1, 'name': 'battery', 'message': 'low', 'hardware_id': 'bms',
                    'values': [{'key': 'percent', 'value': '19'}, {'key': 'cells', 'value': '2'}]}]}))
    out.append(('/behavior_tree_log', 'nav2_msgs/msg/BehaviorTreeLog', t0 + 4, {
        'timestamp': time(1_700_000_004, 0), 'event_log': [
            {'timestamp': time(1_700_000_004, 0), 'node_name': 'FollowPath', 'uid': 12,
             'previous_status': 'IDLE', 'current_status': 'RUNNING'},
            {'timestamp': time(1_700_000_004, 5), 'node_name': 'ComputePathToPose', 'uid': 65535,
             'previous_status': 'RUNNING', 'current_status': 'FAILURE'}]}))
    out.append(('/chatter', 'std_msgs/msg/String', t0 + 5, {'data': 'Hello, wörld'}))
    out.append(('/everything', 'predmon_test/msg/Everything', t0 + 6, {
        'a_int8': -128, 'a_uint8': 255, 'a_int16': -32768, 'a_uint16': 65535, 'a_int32': -2147483648,
        'a_uint32': 4294967295, 'a_int64': -9223372036854775808, 'a_uint64': 18446744073709551615,
        'a_float32': -0.125, 'a_float64': 1e300, 'a_bool': True, 'a_byte': 7, 'a_char': 65, 'a_string': '',
        'bounded_string': 'ten chars!', 'fixed_doubles': [1.5, -2.5, 0.0], 'bounded_ints': [1, -2, 3],
        'some_bytes': [0, 1, 254], 'strings': ['a', '', 'ccc'], 'flags': [True, False],
        'times': [time(1, 2), time(3, 4)], 'header': {'stamp': time(5, 6), 'frame_id': 'map'}}))
    out.append(('/battery_state', 'sensor_msgs/msg/BatteryState', t0 + 7, battery(1, math.nan, [])))
    return out


def to_rosbags(ts, typename, value):
    """A rosbags message object of typename from a dict of plain values."""
    cls = ts.types[typename]
    _, fields = ts.fielddefs[typename]
    args = {}
    for name, (kind, desc) in fields:
        v = value[name]
        if kind.name == 'BASE':
            args[name] = v
        elif kind.name == 'NAME':
            args[name] = to_rosbags(ts, desc, v)
        else:
            (ekind, edesc), _ = desc
            if ekind.name == 'BASE' and edesc[0] != 'string':
                dtype = {'bool': np.bool_, 'byte': np.uint8, 'char': np.uint8, 'int8': np.int8, 'uint8': np.uint8,
                         'int16': np.int16, 'uint16': np.uint16, 'int32': np.int32, 'uint32': np.uint32,
                         'int64': np.int64, 'uint64': np.uint64, 'float32': np.float32,
                         'float64': np.float64}[edesc[0]]
                args[name] = np.array(v, dtype=dtype)
            elif ekind.name == 'BASE':
                args[name] = list(v)
            else:
                args[name] = [to_rosbags(ts, edesc, x) for x in v]
    return cls(**args)


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    ts = get_typestore(Stores.ROS2_JAZZY)
    custom = {}
    custom.update(get_types_from_msg(NAV2_LOG, 'nav2_msgs/msg/BehaviorTreeLog'))
    custom.update(get_types_from_msg(NAV2_CHANGE, 'nav2_msgs/msg/BehaviorTreeStatusChange'))
    custom.update(get_types_from_msg(EVERYTHING, 'predmon_test/msg/Everything'))
    ts.register(custom)
    msgs = messages()
    for plugin, name in [(StoragePlugin.SQLITE3, 'rosbags_sqlite3'), (StoragePlugin.MCAP, 'rosbags_mcap')]:
        with Writer(out / name, version=9, storage_plugin=plugin) as w:
            conns = {}
            for topic, typ, t, fields in msgs:
                if topic not in conns:
                    conns[topic] = w.add_connection(topic, typ, typestore=ts)
                w.write(conns[topic], t, ts.serialize_cdr(to_rosbags(ts, typ, fields), typ))
    for compression, name in [(CompressionType.ZSTD, 'zstd.mcap'), (CompressionType.LZ4, 'lz4.mcap')]:
        with open(out / name, 'wb') as f:
            w = McapRos2Writer(f, compression=compression, chunk_size=256)
            schemas = {}
            for topic, typ, t, fields in msgs:
                if typ not in schemas:
                    # rosbags writes ROS 1's 'time' for builtin_interfaces/Time, which mcap-ros2 does not take
                    text = re.sub(r'^time(\[[^]]*\])? ', r'builtin_interfaces/Time\1 ', ts.generate_msgdef(typ)[0], flags=re.M)
                    schemas[typ] = w.register_msgdef(typ, text)
                w.write_message(topic, schemas[typ], fields, log_time=t, publish_time=t)
            w.finish()
    with open(out / 'expected.json', 'w', encoding='utf-8') as f:
        json.dump([{'topic': topic, 'type': typ, 'log_time': t, 'fields': fields} for topic, typ, t, fields in msgs],
                  f, ensure_ascii=False, indent=1)


if __name__ == '__main__':
    main(Path(sys.argv[1]))
