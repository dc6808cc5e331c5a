#!/usr/bin/python3
"""A stand-in for Chromium's DevTools pipe (--remote-debugging-pipe): reads
NUL-ended JSON commands on descriptor 3 and answers on 4, as the browser does,
so that the PDF writer's protocol client (report/devtools_browser.cpp) is
tested without a browser. FAKE_DEVTOOLS (environment) chooses its behaviour:
  print   (default) every page prints as a small PDF, sent in base 64;
  refuse  Page.printToPDF answers with a protocol error;
  die     the stand-in exits when asked to print (the pipe closes);
  malformed  the PDF's data is a number, not base 64 text.
Absolute interpreter path: the tests run it with PATH=/nonexistent."""
import base64
import json
import os
import sys

mode = os.environ.get("FAKE_DEVTOOLS", "print")
if "--remote-debugging-pipe" not in sys.argv:
    sys.exit(3)
inp, out = os.fdopen(3, "rb", buffering=0), os.fdopen(4, "wb", buffering=0)
PDF = b"%PDF-1.4\n% printed by fake_devtools.py through the DevTools pipe\n%%EOF\n"


def send(msg):
    out.write(json.dumps(msg).encode() + b"\0")


buf = b""
while True:
    chunk = inp.read(65536)
    if not chunk:
        break
    buf += chunk
    while b"\0" in buf:
        raw, buf = buf.split(b"\0", 1)
        m = json.loads(raw)
        method, mid, session = m["method"], m["id"], m.get("sessionId")
        if method == "Browser.close":
            sys.exit(0)
        result = {}
        if method == "Browser.getVersion":
            result = {"product": "fake"}
        elif method == "Target.createTarget":
            result = {"targetId": "T%d" % mid}
        elif method == "Target.attachToTarget":
            result = {"sessionId": "S" + m["params"]["targetId"]}
        elif method == "Page.printToPDF":
            if mode == "die":
                sys.exit(1)
            if mode == "malformed":
                send({"id": mid, "result": {"data": 5}, "sessionId": session})
                continue
            if mode == "refuse":
                send({"id": mid, "error": {"code": -32000, "message": "Printing failed"}, "sessionId": session})
                continue
            result = {"data": base64.b64encode(PDF).decode()}
        answer = {"id": mid, "result": result}
        if session:
            answer["sessionId"] = session
        send(answer)
        if method == "Page.navigate":
            send({"method": "Page.loadEventFired", "params": {"timestamp": 1}, "sessionId": session})
