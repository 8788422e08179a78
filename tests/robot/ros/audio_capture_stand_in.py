#!/usr/bin/python3
# Helper of the ros_audio_topic test: stands in for audio_common's audio_capture node run with
# format wave. Publishes a 16-bit WAV file's frames as audio_common_msgs/AudioData chunks of
# CHUNK_FRAMES frames on TOPIC, paced at the file's rate, from its first frame, round and round, and
# (latched, as audio_capture does) an audio_common_msgs/AudioInfo describing them on TOPIC_info.
#
#   audio_capture_stand_in.py WAV TOPIC CHUNK_FRAMES
#
# The message classes are written by hand from audio_common's definitions (name, md5, wire format),
# not generated from echoplan's copies, so the test checks echoplan's types against the real ones.
import struct
import sys
import wave

import rospy
from genpy import Message


class AudioData(Message):
    _type = "audio_common_msgs/AudioData"
    _md5sum = "f43a8e1b362b75baa741461b46adc7e0"  # audio_common_msgs' own, the md5 of "uint8[] data"
    _has_header = False
    _full_text = "uint8[] data\n"
    __slots__ = ["data"]
    _slot_types = ["uint8[]"]

    def __init__(self, data=b""):
        self.data = data

    def serialize(self, buff):
        buff.write(struct.pack("<I", len(self.data)) + bytes(self.data))

    def deserialize(self, raw):
        (length,) = struct.unpack_from("<I", raw, 0)
        self.data = raw[4 : 4 + length]
        return self


class AudioInfo(Message):
    _type = "audio_common_msgs/AudioInfo"
    _md5sum = "9413d9b7029680d3b1db6ed0ae535f88"  # audio_common_msgs' own
    _has_header = False
    _full_text = "uint8 channels\nuint32 sample_rate\nstring sample_format\nuint32 bitrate\nstring coding_format\n"
    __slots__ = ["channels", "sample_rate", "sample_format", "bitrate", "coding_format"]
    _slot_types = ["uint8", "uint32", "string", "uint32", "string"]

    def __init__(self, channels=0, sample_rate=0, sample_format="", bitrate=0, coding_format=""):
        self.channels, self.sample_rate, self.sample_format = channels, sample_rate, sample_format
        self.bitrate, self.coding_format = bitrate, coding_format

    def serialize(self, buff):
        text = lambda s: struct.pack("<I", len(s)) + s.encode()
        buff.write(struct.pack("<BI", self.channels, self.sample_rate) + text(self.sample_format)
                   + struct.pack("<I", self.bitrate) + text(self.coding_format))

    def deserialize(self, raw):
        raise NotImplementedError("publish only")


def main():
    path, topic, chunk_frames = sys.argv[1], sys.argv[2], int(sys.argv[3])
    with wave.open(path) as w:
        assert w.getsampwidth() == 2, "a 16-bit WAV"
        rate, frame_bytes = w.getframerate(), w.getnchannels() * 2
        frames = w.readframes(w.getnframes())
    assert len(frames) % (chunk_frames * frame_bytes) == 0, "the file is whole chunks"
    rospy.init_node("audio_capture_stand_in", disable_signals=True)
    publisher = rospy.Publisher(topic, AudioData, queue_size=100)
    info = rospy.Publisher(topic + "_info", AudioInfo, queue_size=1, latch=True)
    info.publish(AudioInfo(frame_bytes // 2, rate, "S16LE", 0, "wave"))
    pace = rospy.Rate(rate / chunk_frames)
    chunk_bytes = chunk_frames * frame_bytes
    at = 0
    while not rospy.is_shutdown():
        publisher.publish(AudioData(frames[at : at + chunk_bytes]))
        at = (at + chunk_bytes) % len(frames)
        pace.sleep()


if __name__ == "__main__":
    main()
