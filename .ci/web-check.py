"""Opens platefall's --web page in headless Chromium and checks that the web viewer shows the
run: every few seconds it looks at the Wake view (the top left of the default layout) for both
signs of vorticity, the yellow and the cyan of its colour map, which only a recording that has
loaded and rendered puts there (the loading screen, an error page or an empty viewer are grey),
then saves a screenshot of the whole page. Standard library only: Chromium is driven over the DevTools pipe
(--remote-debugging-pipe, file descriptors 3 and 4) and the PNG is decoded here.

usage: web-check.py URL SHOT.png SECONDS [chromium flags...]
Exit 0 once the check passes, 1 if it has not within SECONDS (the screenshot is saved either way)."""
import base64
import json
import os
import select
import struct
import subprocess
import sys
import time
import zlib

# The Wake view in a 1400 x 900 window (CSS pixels): left three fifths, below the top bar, above
# the close-up.
WAKE = {"x": 50, "y": 60, "width": 740, "height": 350, "scale": 0.5}
# Screenshot pixels of each sign of vorticity needed (of about 65 000 in the clip).
ENOUGH = 150


class DevTools:
    """The DevTools protocol over a pair of pipes: NUL-terminated JSON messages."""

    def __init__(self, to_chrome, from_chrome):
        self.w, self.r, self.buf, self.last_id = to_chrome, from_chrome, b"", 0

    def call(self, method, session=None, timeout=60, **params):
        self.last_id += 1
        msg = {"id": self.last_id, "method": method, "params": params}
        if session:
            msg["sessionId"] = session
        os.write(self.w, json.dumps(msg).encode() + b"\0")
        deadline = time.time() + timeout
        while True:
            reply = self.read(deadline)
            if reply.get("id") == self.last_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})

    def read(self, deadline):
        while b"\0" not in self.buf:
            left = deadline - time.time()
            if left <= 0 or not select.select([self.r], [], [], left)[0]:
                raise TimeoutError("no reply from chromium")
            chunk = os.read(self.r, 1 << 20)
            if not chunk:
                raise EOFError("chromium closed the DevTools pipe")
            self.buf += chunk
        msg, self.buf = self.buf.split(b"\0", 1)
        return json.loads(msg)


def pixels(png):
    """(width, height, channels, rows of bytes) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    pos, idat, width = 8, b"", None
    while pos < len(png):
        (n,) = struct.unpack(">I", png[pos:pos + 4])
        kind, body = png[pos + 4:pos + 8], png[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), "8-bit RGB or RGBA"
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride = zlib.decompress(idat), width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def vorticity_signs(png):
    """Pixels towards the colour map's two ends: (yellow, cyan)."""
    width, _, ch, rows = pixels(png)
    yellow = cyan = 0
    for line in rows:
        for x in range(width):
            r, g, b = line[x * ch], line[x * ch + 1], line[x * ch + 2]
            # The view's grey background and the UI have r ≈ g ≈ b.
            yellow += r - b > 60
            cyan += b - r > 60
    return yellow, cyan


def main():
    url, shot, seconds, flags = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4:]
    to_r, to_w = os.pipe()
    from_r, from_w = os.pipe()

    def devtools_fds():
        # Through free numbers first: the pipes may already be 3 or 4.
        a, b = os.dup(to_r), os.dup(from_w)
        for fd, target in ((a, 3), (b, 4)):
            os.dup2(fd, target)
            os.set_inheritable(target, True)

    log = open(shot + ".log", "w")
    chrome = subprocess.Popen(
        ["chromium", "--headless", "--remote-debugging-pipe", *flags, "about:blank"],
        preexec_fn=devtools_fds, close_fds=False, stdout=log, stderr=log)
    os.close(to_r)
    os.close(from_w)
    found, deadline = (0, 0), time.time() + seconds
    try:
        tools = DevTools(to_w, from_r)
        target = tools.call("Target.createTarget", url=url)["targetId"]
        session = tools.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        while time.time() < deadline and min(found) < ENOUGH:
            time.sleep(3)
            wake = tools.call("Page.captureScreenshot", session=session, format="png", clip=WAKE)
            found = vorticity_signs(base64.b64decode(wake["data"]))
        page = tools.call("Page.captureScreenshot", session=session, format="png")
        with open(shot, "wb") as f:
            f.write(base64.b64decode(page["data"]))
        title = tools.call("Runtime.evaluate", session=session, expression="document.title")
        print(f"page title {title['result'].get('value')!r}; Wake view: {found[0]} yellow and "
              f"{found[1]} cyan pixels (positive and negative vorticity), {ENOUGH} of each needed")
    finally:
        chrome.kill()
        chrome.wait(timeout=30)
    return 0 if min(found) >= ENOUGH else 1


if __name__ == "__main__":
    sys.exit(main())
