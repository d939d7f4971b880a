"""Reading a recording back with the ``mcap`` library itself (as Foxglove or a script would)."""
import json

from mcap.reader import make_reader
from mcap_ros1.decoder import DecoderFactory


def channels_and_messages(path):
    """``({topic: (message encoding, schema name, schema encoding)}, {topic: [decoded messages]})``:
    ROS 1 channels decoded with mcap-ros1-support (genpy messages), JSON ones as dicts."""
    found, messages, ros1 = {}, {}, DecoderFactory()
    with open(path, "rb") as stream:
        for schema, channel, message in make_reader(stream).iter_messages(log_time_order=True):
            found[channel.topic] = (channel.message_encoding, schema.name, schema.encoding)
            if channel.message_encoding == "json":
                decoded = json.loads(message.data)
            else:
                decoded = ros1.decoder_for(channel.message_encoding, schema)(message.data)
            messages.setdefault(channel.topic, []).append(decoded)
    return found, messages


def metadata_and_attachments(path):
    """``({name: metadata}, {name: bytes})`` of a finished recording."""
    with open(path, "rb") as stream:
        reader = make_reader(stream)
        metadata = {record.name: dict(record.metadata) for record in reader.iter_metadata()}
    with open(path, "rb") as stream:
        attachments = {record.name: bytes(record.data) for record in make_reader(stream).iter_attachments()}
    return metadata, attachments
