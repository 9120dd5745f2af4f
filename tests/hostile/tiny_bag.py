"""Hand-made ROS 1 bags for the hostile cases: one uncompressed chunk, one index entry a message.

    python3 tiny_bag.py cloud|cloud2|undeclared > FILE.bag

cloud: a sensor_msgs/PointCloud whose points claim 2^31 - 1 elements (24 GiB); cloud2: a
PointCloud2 of one point whose data claims 1.5e9 bytes (both with an intact odometry message);
undeclared: a chunk info that counts a message of connection 1, which no record declares.
"""
import struct
import sys


def u32(v): return struct.pack("<I", v)
def u64(v): return struct.pack("<Q", v)


def fields(fs):
    return b"".join(u32(len(k) + 1 + len(v)) + k.encode() + b"=" + v for k, v in fs)


def record(header, data):
    h = fields(header)
    return u32(len(h)) + h + u32(len(data)) + data


def string(s): return u32(len(s)) + s
def header(sec): return u32(0) + u32(sec) + u32(0) + string(b"")


def conn(c, topic, type_, md5=b"0" * 32):
    return record([("op", b"\x07"), ("conn", u32(c)), ("topic", topic)],
                  fields([("topic", topic), ("type", type_), ("md5sum", md5),
                          ("message_definition", b"")]))


def message(c, sec, data):
    return record([("op", b"\x02"), ("conn", u32(c)), ("time", u32(sec) + u32(0))], data)


def bag_header(index_pos, conn_count):  # padded to 4096 bytes, as rosbag writes it
    h = fields([("op", b"\x03"), ("index_pos", u64(index_pos)), ("conn_count", u32(conn_count)),
                ("chunk_count", u32(1))])
    return u32(len(h)) + h + u32(4096 - len(h)) + b" " * (4096 - len(h))


def one_chunk_bag(data, entries, conn_records, conn_count, start, end):
    """data: the chunk's records; entries: (connection, seconds, offset in the chunk) of each
    message, one index data record each; conn_records: the connection records after the index."""
    chunk = record([("op", b"\x05"), ("compression", b"none"), ("size", u32(len(data)))], data)
    index = b"".join(record([("op", b"\x04"), ("ver", u32(1)), ("conn", u32(c)), ("count", u32(1))],
                            u32(sec) + u32(0) + u32(offset)) for c, sec, offset in entries)
    magic = b"#ROSBAG V2.0\n"
    chunk_pos = len(magic) + len(bag_header(0, conn_count))
    info = record([("op", b"\x06"), ("ver", u32(1)), ("chunk_pos", u64(chunk_pos)),
                   ("start_time", u32(start) + u32(0)), ("end_time", u32(end) + u32(0)),
                   ("count", u32(len(entries)))], b"".join(u32(c) + u32(1) for c, _, _ in entries))
    return (magic + bag_header(chunk_pos + len(chunk) + len(index), conn_count) + chunk + index +
            conn_records + info)


def damaged_sonar(kind):
    if kind == "cloud":
        sonar = (b"sensor_msgs/PointCloud", b"d8e9c3f5afbdd8a130fd1d2763945fca",
                 header(100) + u32(0x7fffffff) + u32(0))
    else:
        def field(n, off): return string(n) + u32(off) + b"\x07" + u32(1)
        sonar = (b"sensor_msgs/PointCloud2", b"1158d486dd51d683ce2f1be655c3c181",
                 header(100) + u32(1) + u32(1) + u32(2) + field(b"x", 0) + field(b"y", 4) +
                 b"\x00" + u32(8) + u32(8) + u32(1500000000) + bytes(8) + b"\x00")
    odometry = (header(101) + string(b"base_link") + struct.pack("<7d", 0, 0, 0, 0, 0, 0, 1) +
                bytes(78 * 8))
    conns = (conn(0, b"/RosAria/pose", b"nav_msgs/Odometry", b"cd5e73d190d741a2f92e81eda573aca7") +
             conn(1, b"/RosAria/sonar", sonar[0], sonar[1]))
    data = conns
    sonar_at = len(data)
    data += message(1, 100, sonar[2])
    odometry_at = len(data)
    data += message(0, 101, odometry)
    return one_chunk_bag(data, [(0, 101, odometry_at), (1, 100, sonar_at)], conns, 2, 100, 101)


def undeclared():
    # One chunk: the odometry's connection record, one message of connection 0 and one of 1;
    # the index declares connection 0 only, its chunk info counts a message of 1 as well.
    odometry = conn(0, b"/RosAria/pose", b"nav_msgs/Odometry")
    data = odometry
    offsets = [len(data), len(data) + len(message(0, 100, bytes(8)))]
    data += message(0, 100, bytes(8)) + message(1, 100, bytes(8))
    return one_chunk_bag(data, [(0, 100, offsets[0]), (1, 100, offsets[1])], odometry, 1, 100, 100)


if __name__ == "__main__":
    kind = sys.argv[1]
    sys.stdout.buffer.write(undeclared() if kind == "undeclared" else damaged_sonar(kind))
