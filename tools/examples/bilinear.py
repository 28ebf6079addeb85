#!/usr/bin/env python3
"""An outside sampler for texsample's `lookup` file protocol (doc/backends.md).

OpenGL's GL_LINEAR on the base level (GL 4.6 §8.14.2, no mipmaps), for
wrap modes repeat and clamp_to_edge; any other mode is "n/a" (exit 3 with
the reason). Python 3 alone, no numpy. Row of `compare`/`freq`:

  texsample compare --backend-program 'py-bilinear=python3 tools/examples/bilinear.py'
"""
import math, struct, sys

def main(argv):
    opt = dict(zip(argv[0::2], argv[1::2]))  # every option takes one value
    w, h = int(opt["--w"]), int(opt["--h"])
    for axis in ("--wrap-s", "--wrap-t"):
        if opt.get(axis, "repeat") not in ("repeat", "clamp_to_edge"):
            print("bilinear.py does only repeat and clamp_to_edge, not " + opt[axis])
            return 3
    with open(opt["--raw"], "rb") as f:
        tex = struct.unpack("<%df" % (w * h * 4), f.read())
    with open(opt["--queries"], "rb") as f:
        data = f.read()
    q = struct.unpack("<%df" % (len(data) // 4), data)

    def wrap(i, n, mode):
        return i % n if mode == "repeat" else min(max(i, 0), n - 1)

    out = []
    for k in range(0, len(q), 6):
        u, v = q[k] * w - 0.5, q[k + 1] * h - 0.5  # texel centres at +1/2
        i0, j0 = math.floor(u), math.floor(v)
        a, b = u - i0, v - j0
        i = [wrap(i0, w, opt.get("--wrap-s", "repeat")), wrap(i0 + 1, w, opt.get("--wrap-s", "repeat"))]
        j = [wrap(j0, h, opt.get("--wrap-t", "repeat")), wrap(j0 + 1, h, opt.get("--wrap-t", "repeat"))]
        for c in range(4):
            t = [[tex[4 * (jj * w + ii) + c] for ii in i] for jj in j]
            out.append((1 - b) * ((1 - a) * t[0][0] + a * t[0][1]) + b * ((1 - a) * t[1][0] + a * t[1][1]))
    with open(opt["--out"], "wb") as f:
        f.write(struct.pack("<%df" % len(out), *out))
    return 0

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
