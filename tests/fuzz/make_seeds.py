#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes the seed corpora in corpus/<target>/ from the shared fixtures (real files from
mqtt_client, the benchmarking suite and mqtt_bridge, see ../shared/fixtures/README.md) and a few
hand-made inputs. Run it again after a fixture changes; fuzz_runfile's seed comes from
make_runfile_seed (a real run file written by RunFile::write), see corpus/README.md.

    tests/fuzz/make_seeds.py [FIXTURES_DIR]
"""
import pathlib
import shutil
import struct
import sys

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
fixtures = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else root.parent / "shared" / "fixtures"
if not (fixtures / "README.md").exists():
    fixtures = root / "tests" / "data" / "fixtures"
wire = fixtures / "mqtt_client" / "wire"


def put(target, name, data):
    d = here / "corpus" / target
    d.mkdir(parents=True, exist_ok=True)
    (d / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def ros_string(s):
    b = s.encode()
    return struct.pack("<I", len(b)) + b


def announcement(path):
    """(md5, name, definition, stamped) of a captured type announcement."""
    b = path.read_bytes()
    out, pos = [], 0
    for _ in range(3):
        (n,) = struct.unpack_from("<I", b, pos)
        out.append(b[pos + 4:pos + 4 + n].decode())
        pos += 4 + n
    return out[0], out[1], out[2], b[pos] != 0


# fuzz_rosmessage: "TYPE\nDEFINITION\0PAYLOAD"
for kind in ("header", "pose", "string_stamped"):
    md5, name, definition, stamped = announcement(wire / f"{kind}.type.bin")
    payload = (wire / f"{kind}.payload.bin").read_bytes()
    if stamped:
        payload = payload[8:]
    put("rosmessage", kind, name.encode() + b"\n" + definition.encode() + b"\0" + payload)
header_def = announcement(wire / "header.type.bin")[2]
timestamped_def = (fixtures / "benchmarking_suite" / "TimeStamped.msg").read_text() + "\n" + "=" * 80 + \
    "\nMSG: std_msgs/Header\n" + header_def
timestamped = struct.pack("<III", 1, 1700000000, 5) + ros_string("vehicle") + struct.pack("<II", 1700000000, 40000000)
put("rosmessage", "timestamped", b"benchmarking_suite/TimeStamped\n" + timestamped_def.encode() + b"\0" + timestamped)
put("rosmessage", "arrays", b"pkg/Arrays\nuint8[] data\nInner[2] fixed\nstring[] names\n" + b"=" * 80 +
    b"\nMSG: pkg/Inner\nfloat64 x\nduration d\n\0" + struct.pack("<I", 3) + b"abc" + bytes(32) +
    struct.pack("<I", 2) + ros_string("a") + ros_string("bc"))

# fuzz_mqttwire: 16-bit length, type announcement, payload
for kind in ("header", "pose", "string_stamped"):
    t = (wire / f"{kind}.type.bin").read_bytes()
    put("mqttwire", kind, struct.pack("<H", len(t)) + t + (wire / f"{kind}.payload.bin").read_bytes())
put("mqttwire", "int_primitive", struct.pack("<H", 0) + (wire / "int_primitive.payload.bin").read_bytes())
ts_announcement = ros_string("6c3188ca087b31af579ede0943a09e20") + ros_string("benchmarking_suite/TimeStamped") + \
    ros_string(timestamped_def) + b"\x01"
put("mqttwire", "timestamped_stamped", struct.pack("<H", len(ts_announcement)) + ts_announcement +
    struct.pack("<II", 1700000000, 50000000) + timestamped)
put("mqttwire", "json_stamp", struct.pack("<H", 0) + b'{"sample": "1700000000.000000005", "time": 1700000000.25}')


class Cdr:
    """Plain CDR (XCDR1) as ROS 2's RMWs write it: a 4-byte encapsulation header (00 01 little-
    endian, 00 00 big-endian), each value aligned to its size from the header's end, strings as a
    uint32 length that counts the NUL, the bytes and the NUL."""

    def __init__(self, order="<"):
        self.order = order
        self.data = bytearray(b"\x00\x01\x00\x00" if order == "<" else b"\x00\x00\x00\x00")

    def put(self, fmt, value):
        size = struct.calcsize("<" + fmt)
        self.data += bytes(-(len(self.data) - 4) % size)
        self.data += struct.pack(self.order + fmt, value)
        return self

    def string(self, s):
        b = s.encode() + b"\0"
        self.put("I", len(b))
        self.data += b
        return self


def ros2_announcement(name, stamped, order="<"):
    """mqtt_client_interfaces/msg/RosMsgType as mqtt_client for ROS 2 sends it (name and stamped set)."""
    return bytes(Cdr(order).string("").string(name).string("").put("?", stamped).data)


# mqtt_client for ROS 2: the hand-written fixtures of tests/unit/tst_mqttclientros2.cpp (checked
# there against Fast CDR): a stamped std_msgs/msg/String, and a big-endian PoseStamped.
a = ros2_announcement("std_msgs/msg/String", True)
put("mqttwire", "ros2_string_stamped", struct.pack("<H", len(a)) + a +
    bytes(Cdr().put("i", 1700000000).put("I", 250000000).data) + bytes(Cdr().string("hello").data))
a = ros2_announcement("geometry_msgs/msg/PoseStamped", False, ">")
pose = Cdr(">").put("i", 12).put("I", 34).string("map")
for v in (4.25, 2.5, -1.0, 0.0, 0.0, 0.0, 1.0):
    pose.put("d", v)
put("mqttwire", "ros2_pose_be", struct.pack("<H", len(a)) + a + bytes(pose.data))

# fuzz_stamps: the same bytes go to every decoder
put("stamps", "timestamped", timestamped)
put("stamps", "header", (wire / "header.payload.bin").read_bytes())
put("stamps", "json_sec_nsec", b'{"sample": "1700000000.000000005", "time": "1700000000.040000000"}')
put("stamps", "json_seconds", b'{"sample": "frame-17", "time": 1700000000.04}')
put("stamps", "time_text", b"1700000000.123456789")
put("stamps", "float64", struct.pack("<d", 1700000000.125))

# fuzz_payloadtext
put("payloadtext", "json", b'{"a": [1, 2.5, "x"], "b": {"c": null, "d": true}}')
put("payloadtext", "text", b"hello mqtt\nline two\ttab\r\n")
put("payloadtext", "binary", (wire / "pose.payload.bin").read_bytes())
put("payloadtext", "int_primitive", (wire / "int_primitive.payload.bin").read_bytes())
put("payloadtext", "utf8", "Grüße ✓ 🚗".encode())

# fuzz_config: real configs of every layout (the last byte picks the edit)
for sub, pattern in (("mqtt_client", "*.yaml"), ("benchmarking_suite", "mqtt_*.yaml"), ("mqtt_bridge", "*.yaml")):
    for f in sorted((fixtures / sub).glob(pattern)):
        put("config", f"{sub}-{f.name}", f.read_bytes())

# fuzz_pipeline
for f in sorted((fixtures / "benchmarking_suite").glob("metrics_logger_*.yaml")):
    put("pipeline", f.name, f.read_bytes())
put("pipeline", "hosts.yaml", "topics_in_order:\n  - /a/in\n  - /a/out\n  - /b/in\nmetrics_window: 100\n"
    "hosts:\n  /a/in: vehicle\n  /a/out: vehicle\n  /b/in: cloud\n")

# fuzz_names: a name, NUL, a filter
for i, (name, flt) in enumerate([("/benchmarking_suite/timestamps/in", "a/+/c"),
                                 ("mqtt_client/ros_msg_type/cap/pose", "mqtt_client/ros_msg_type/#"),
                                 ("~/private_ns/topic", "$SYS/broker/#"),
                                 ("vehicle/pointcloud", "+/pointcloud")]):
    put("names", f"name{i}", name.encode() + b"\0" + flt.encode())

# fuzz_suitecsv keeps its hand-made seeds (suite.csv is what the suite's logger writes).

# fuzz_ros2frames: what bridgescope-dds writes (core/ros2/ros2protocol.h), a slice-size byte first
def frame(kind, body=b""):
    return struct.pack("<IB", len(body), kind) + body

def pstr(s):
    b = s.encode()
    return struct.pack("<I", len(b)) + b

def pstrs(items):
    return struct.pack("<I", len(items)) + b"".join(pstr(s) for s in items)

def endpoint(gid, topic, typ, publisher, node):
    return (struct.pack("<I", 16) + gid + pstr(topic) + pstr(typ) + bytes([publisher, 0, 1])
            + struct.pack("<i", -1) + pstr(node))

STARTED, GRAPH, STATS, SAMPLES, ARRIVALS, MONITOR_FAILED, HEARTBEAT = 64, 66, 67, 68, 69, 70, 71
graph = (struct.pack("<QIIQ", 0, 2, 1, 0) + struct.pack("<I", 1) + pstr("/chatter") + pstrs(["std_msgs/msg/String"])
         + struct.pack("<I", 1) + endpoint(bytes(range(16)), "/chatter", "std_msgs/msg/String", 1, "/lab/talker")
         + struct.pack("<I", 0) + struct.pack("<I", 1) + pstr("/lab/talker") + pstrs(["/chatter"]) + pstrs([]))
string_cdr = b"\x00\x01\x00\x00" + struct.pack("<I", 6) + b"hello\x00"
samples = pstr("/chatter") + struct.pack("<QI", 0, 2) + b"".join(
    struct.pack("<q", 1_700_000_000_000_000_000 + i) + struct.pack("<I", len(string_cdr)) + string_cdr for i in range(2))
stats = (struct.pack("<I", 1) + pstr("/chatter") + struct.pack("<QQIq", 2, 24, 12, 1_700_000_000_000_000_000)
         + struct.pack("<dd", 10.0, 120.0) + pstr("std_msgs/msg/String") + struct.pack("<QI", 0, 1) + b"\x01"
         + struct.pack("<I", len(string_cdr)) + string_cdr)
arrivals = struct.pack("<QI", 0, 1) + pstr("/chatter") + struct.pack("<qI", 1, 12) + struct.pack("<I", 8) + string_cdr[4:12]
put("ros2frames", "session", b"\x07" + frame(STARTED) + frame(GRAPH, graph) + frame(STATS, stats)
    + frame(SAMPLES, samples) + frame(ARRIVALS, arrivals) + frame(HEARTBEAT))
put("ros2frames", "monitor-failed", b"\x01" + frame(MONITOR_FAILED, pstr("/nobody") + pstr("no type yet")))
put("ros2frames", "graph-only", b"\x40" + frame(GRAPH, graph))

# fuzz_ddschild: what the parent writes to bridgescope-dds (core/ros2/ros2protocol.h): a slice-size
# byte, a frames-per-turn byte, then the frames
START, MONITOR, UNMONITOR, WATCH, UNWATCH, KEEP_ARRIVALS, GRAPH_INTERVAL, SET_NODE, ADVERTISE, UNADVERTISE, \
    PUBLISH, SUBSCRIBE, UNSUBSCRIBE = range(1, 14)

def endpoint_request(topic, typ, depth=10):
    return pstr(topic) + pstr(typ) + bytes([1, 0]) + struct.pack("<I", depth)

put("ddschild", "bridge", b"\x10\x03" + frame(START, struct.pack("<IBI", 42, 1, 250))
    + frame(KEEP_ARRIVALS, struct.pack("<Q", 1000)) + frame(WATCH, pstr("/chatter") + struct.pack("<Qq", 100, 1 << 20))
    + frame(MONITOR, pstr("/chatter")) + frame(SET_NODE, pstr("/") + pstr("mqtt_client"))
    + frame(ADVERTISE, endpoint_request("/from_mqtt", "std_msgs/msg/String"))
    + frame(SUBSCRIBE, endpoint_request("/to_mqtt", "geometry_msgs/msg/PoseStamped"))
    + frame(PUBLISH, pstr("/from_mqtt") + struct.pack("<I", len(string_cdr)) + string_cdr)
    + frame(GRAPH_INTERVAL, struct.pack("<Q", 100)) + frame(UNMONITOR, pstr("/chatter"))
    + frame(UNWATCH, pstr("/chatter")) + frame(UNADVERTISE, pstr("/from_mqtt")) + frame(UNSUBSCRIBE, pstr("/to_mqtt")))
# issue 41: a 70,000-character type name, a type flipped with every message, a name past 255
put("ddschild", "hostile-types", b"\xff\x07" + frame(ADVERTISE, endpoint_request("/t", "a" * 70000 + "/msg/T"))
    + b"".join(frame(ADVERTISE, endpoint_request("/flip", f"flip_msgs/msg/T{i}")) for i in range(40))
    + frame(SUBSCRIBE, endpoint_request("/" + "x" * 300, "std_msgs/msg/String"))
    + frame(ADVERTISE, endpoint_request("/t", "std_msgs::msg::dds_::String_")))

# fuzz_ros2graph: a generated-endpoints byte, a budget byte, then records (participant, flags,
# topic length, topic, type length, type)
def graph_record(participant, flags, topic, typ):
    t, y = topic.encode(), typ.encode()
    return bytes([participant, flags, len(t)]) + t + bytes([len(y)]) + y

put("ros2graph", "lab", b"\x00\xff" + graph_record(0, 17, "/chatter", "std_msgs/msg/String")
    + graph_record(1, 16, "/chatter", "std_msgs/msg/String") + graph_record(2, 3, "/pose", "geometry_msgs/msg/PoseStamped"))
put("ros2graph", "one-topic-many-types", b"\x15\x20" + graph_record(0, 17, "/flood", "std_msgs/msg/String"))
put("ros2graph", "long-names", b"\x00\x08" + b"".join(
    graph_record(3, 1, "/" + chr(97 + i) * 250, "t" * 250) for i in range(20)))

# fuzz_clockprobe: probes and answers (docs/formats.md, "Clock probes"): 288 bytes, little-endian.
def clock_probe(kind, nonce, t1, t2=0, t3=0, name="", reply="", sync=None):
    n, r = name.encode(), reply.encode()
    head = b"BSCK" + bytes([1, kind, len(n), len(r)]) + struct.pack("<Qqqq", nonce, t1, t2, t3)
    body = n.ljust(64, b"\0") + r.ljust(120, b"\0")
    if sync is None:
        return head + body + bytes(64)
    source, status, ref, values = sync
    ref = ref.encode()
    return head + body + bytes([source, status, len(ref), 0]) + struct.pack("<5q", *values) + ref.ljust(20, b"\0")

t1 = 1732860000123456789
put("clockprobe", "udp-probe", clock_probe(1, 1, t1))
put("clockprobe", "mqtt-probe", clock_probe(1, 2, t1, name="cloud", reply="bridgescope/clock/cloud/reply/vehicle-1"))
put("clockprobe", "answer", clock_probe(2, 1, t1, t1 + 35000000, t1 + 35020000, name="cloud"))
put("clockprobe", "answer-chrony", clock_probe(2, 3, t1, t1 + 5, t1 + 9, name="wolke-\u00fc",
                                               sync=(1, 0, "169.254.169.123", (-1234, 543210, 123456, -12345, 50))))
put("clockprobe", "answer-ptp", clock_probe(2, 4, t1, t1 - 250000000, t1 - 249990000, name="edge",
                                            sync=(2, 1, "90e2ba.fffe.2a8b3c", (-12, 0, 0, 0, 0))))
put("clockprobe", "short", clock_probe(1, 1, t1)[:100])
