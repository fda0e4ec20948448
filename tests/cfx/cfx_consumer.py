#!/usr/bin/python3
"""An independent CFX consumer for the tests: Qpid Proton's Python binding, knowing only the
CFX SDK's names and docs/cfx.md. It receives from an AMQP 1.0 source, unpacks gzip bodies,
checks each envelope and its AMQP properties as the SDK's AmqpUtilities sets them, and prints
one JSON line per message ("BAD: ..." lines for what does not fit), "READY" once it listens.
It stops after --count messages, or fails after --timeout seconds."""

import argparse
import gzip
import json
import sys
import time
import uuid

from proton import Message
from proton.handlers import MessagingHandler
from proton.reactor import Backoff, Container

ENVELOPE = ["MessageName", "Version", "TimeStamp", "UniqueID", "Source", "Target",
            "RequestID", "MessageBody"]


def is_uuid(text):
    try:
        uuid.UUID(str(text))
        return True
    except ValueError:
        return False


def first_key_is_type(obj, type_name):
    """Newtonsoft reads a polymorphic object only when "$type" comes first."""
    return isinstance(obj, dict) and next(iter(obj), None) == "$type" and \
        obj["$type"] == type_name


def check_numeric_values(items, where, bad):
    for item in items or []:
        value = item.get("Value", {})
        if not isinstance(item.get("Name"), str) or \
                not isinstance(value.get("Value"), (int, float)) or \
                not isinstance(value.get("ValueUnits"), str):
            bad.append("%s value %r" % (where, item))


def check_body(name, body):
    """The fields of the messages the SDK declares, by its names (docs/cfx.md)."""
    bad = []
    if next(iter(body), None) != "$type":
        bad.append("$type is not the body's first field")
    if name == "CFX.Production.WorkStarted":
        if not is_uuid(body.get("TransactionID")) or not isinstance(body.get("PrimaryIdentifier"), str):
            bad.append("WorkStarted ids %r" % body)
        if body.get("UnitCount") != len(body.get("Units") or []):
            bad.append("WorkStarted UnitCount")
        if body.get("RelevantSurface") not in ("Unspecified", "PrimarySurface", "SecondarySurface"):
            bad.append("WorkStarted RelevantSurface")
    elif name == "CFX.Production.WorkCompleted":
        if not is_uuid(body.get("TransactionID")):
            bad.append("WorkCompleted TransactionID")
        if body.get("Result") not in ("Completed", "Failed", "Aborted", "Skipped"):
            bad.append("WorkCompleted Result %r" % body.get("Result"))
    elif name == "CFX.Production.Processing.UnitsProcessed":
        results = ("Succeeded", "Failed", "Error", "Aborted", "Skipped")
        if not is_uuid(body.get("TransactionId")) or "TransactionID" in body:
            bad.append("UnitsProcessed TransactionId")
        if body.get("OverallResult") not in results:
            bad.append("UnitsProcessed OverallResult")
        common = body.get("CommonProcessData")
        if not first_key_is_type(
                common, "CFX.Structures.HandSoldering.HandSolderingBoardProcessData, CFX"):
            bad.append("CommonProcessData $type")
        else:
            if not is_uuid(common.get("BoardId")):
                bad.append("BoardId")
            for point in common.get("SolderPoints") or []:
                for key in ("Name", "StartedAt", "FinishedAt"):
                    if not isinstance(point.get(key), str):
                        bad.append("SolderPoint " + key)
                for material in point.get("Materials") or []:
                    if not isinstance(material.get("Type"), int):  # MaterialType: a number
                        bad.append("Material Type %r" % material.get("Type"))
        for unit in body.get("UnitProcessData") or []:
            if unit.get("UnitResult") not in results:
                bad.append("UnitResult")
            data = unit.get("UnitProcessData")
            if data is None:
                continue
            if not first_key_is_type(data, "CFX.Structures.Generic.GenericProcessData, CFX"):
                bad.append("UnitProcessData $type")
                continue
            check_numeric_values(data.get("Setpoints"), "Setpoints", bad)
            check_numeric_values(data.get("Readings"), "Readings", bad)
            for stage in data.get("StageData") or []:
                check_numeric_values(stage.get("Setpoints"), "stage Setpoints", bad)
                check_numeric_values(stage.get("Readings"), "stage Readings", bad)
    elif name == "CFX.ResourcePerformance.StationStateChanged":
        for key in ("OldState", "NewState"):  # ResourceState: its code as text
            if not isinstance(body.get(key), str) or not body[key].isdigit():
                bad.append("%s %r" % (key, body.get(key)))
    return bad


def check(message, envelope):
    """What in one message does not fit CFX, as a list of sentences."""
    bad = []
    missing = [k for k in ENVELOPE if k not in envelope]
    if missing:
        return ["envelope without " + ", ".join(missing)]
    name = envelope["MessageName"]
    body = envelope["MessageBody"]
    if envelope["Version"] != "2.1":
        bad.append("Version " + str(envelope["Version"]))
    if body.get("$type") != name + ", CFX":
        bad.append("$type " + str(body.get("$type")))
    bad += check_body(name, body)
    try:
        uuid.UUID(envelope["UniqueID"])
    except ValueError:
        bad.append("UniqueID " + envelope["UniqueID"])
    if str(message.id) != envelope["UniqueID"]:
        bad.append("message-id " + str(message.id))
    if message.subject != "%s.%s" % (envelope["Source"], name):
        bad.append("subject " + str(message.subject))
    if message.reply_to != envelope["Source"]:
        bad.append("reply-to " + str(message.reply_to))
    if message.content_type != 'application/json; charset="utf-8"':
        bad.append("content-type " + str(message.content_type))
    props = message.properties or {}
    expected = {"cfx-topic": name.rsplit(".", 1)[0], "cfx-message": name,
                "cfx-handle": envelope["Source"], "cfx-target": envelope["Target"]}
    for key, value in expected.items():
        if key not in props or props[key] != value:
            bad.append("%s %r" % (key, props.get(key, "(absent)")))
    return bad


class Consumer(MessagingHandler):
    def __init__(self, url, source, count, timeout, retry_max_s=10):
        super().__init__()
        self.url, self.source, self.count, self.timeout = url, source, count, timeout
        self.retry_max_s = retry_max_s
        self.received = 0
        self.failed = False

    def on_start(self, event):
        connection = event.container.connect(self.url, allowed_mechs="ANONYMOUS PLAIN",
                                             user="guest", password="guest",
                                             allow_insecure_mechs=True,
                                             reconnect=Backoff(max_delay=self.retry_max_s))
        event.container.create_receiver(connection, self.source)
        self.timer = event.container.schedule(self.timeout, self)

    def on_link_opened(self, event):
        if event.receiver:
            print("READY", flush=True)

    def on_timer_task(self, event):
        print("BAD: timeout after %d messages" % self.received, flush=True)
        self.failed = True
        event.container.stop()

    def on_message(self, event):
        message = event.message
        raw = message.body
        if isinstance(raw, memoryview):
            raw = raw.tobytes()
        if message.content_encoding == "gzip":
            raw = gzip.decompress(raw)
        envelope = json.loads(raw.decode("utf-8"))
        for sentence in check(message, envelope):
            print("BAD: %s: %s" % (envelope.get("MessageName"), sentence), flush=True)
        print(json.dumps({"subject": message.subject, "encoding": message.content_encoding,
                          "arrived_ms": int(time.time() * 1000), "envelope": envelope}),
              flush=True)
        self.received += 1
        if self.received >= self.count:
            # Closed, not stopped: the container ends once the broker confirmed the close.
            self.timer.cancel()
            event.receiver.close()
            event.connection.close()

    def on_transport_error(self, event):
        print("BAD: transport %s" % event.transport.condition, flush=True)


class Requester(Consumer):
    """Asks an endpoint as an SDK requester would: each request an envelope with a RequestID, sent
    to the endpoint's request queue with --source as its reply-to; the answers are received and
    printed as messages are, each checked to answer its request."""

    def __init__(self, url, source, count, timeout, names, target, send_to, compress):
        super().__init__(url, source, count, timeout)
        self.names, self.target, self.send_to, self.compress = names, target, send_to, compress
        self.sent = False
        self.asked = {}  # RequestID -> the request's AMQP message-id

    def on_link_opened(self, event):
        super().on_link_opened(event)
        if event.receiver:
            event.container.create_sender(event.connection, self.send_to)

    def on_sendable(self, event):
        if self.sent:
            return
        self.sent = True
        for i, name in enumerate(self.names):
            request_id = "REQUEST-%s" % uuid.uuid4()
            envelope = {"MessageName": name, "Version": "2.1",
                        "TimeStamp": "2026-12-06T12:00:00.000Z", "UniqueID": str(uuid.uuid4()),
                        "Source": "MES.Test.1", "Target": self.target, "RequestID": request_id,
                        "MessageBody": {"$type": name + ", CFX", "CFXHandle": self.target}}
            raw = json.dumps(envelope).encode("utf-8")
            message = Message(body=gzip.compress(raw) if self.compress else raw,
                              id="request-%d" % i, reply_to=self.source,
                              content_type='application/json; charset="utf-8"',
                              subject="MES.Test.1." + name)
            message.inferred = True  # one Data section, as the SDK sends
            if self.compress:
                message.content_encoding = "gzip"
            self.asked[request_id] = message.id
            event.sender.send(message)

    def on_message(self, event):
        message = event.message
        raw = message.body.tobytes() if isinstance(message.body, memoryview) else message.body
        envelope = json.loads(raw.decode("utf-8"))
        asked = self.asked.get(envelope.get("RequestID"))
        if asked is None:
            print("BAD: an answer to no request: %r" % envelope.get("RequestID"), flush=True)
        elif str(message.correlation_id) != asked:
            print("BAD: correlation-id %r for %r" % (message.correlation_id, asked), flush=True)
        if envelope.get("Target") != "MES.Test.1" or message.address not in (None, "MES.Test.1"):
            print("BAD: answered to %r" % envelope.get("Target"), flush=True)
        super().on_message(event)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--url", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--count", type=int, required=True)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--request", action="append", default=[],
                        help="ask this (a CFX request's name) of --target, at --send-to")
    parser.add_argument("--target")
    parser.add_argument("--send-to")
    parser.add_argument("--gzip", action="store_true")
    parser.add_argument("--retry-max-s", type=float, default=10,
                        help="the longest wait before connecting again after a loss")
    args = parser.parse_args()
    if args.request:
        consumer = Requester(args.url, args.source, args.count, args.timeout, args.request,
                             args.target, args.send_to, args.gzip)
    else:
        consumer = Consumer(args.url, args.source, args.count, args.timeout, args.retry_max_s)
    try:
        Container(consumer).run()
    except Exception as error:  # said as a complaint, so the test shows it
        print("BAD: the consumer failed: %r" % error, flush=True)
        return 3
    return 2 if consumer.failed else 0


if __name__ == "__main__":
    sys.exit(main())
