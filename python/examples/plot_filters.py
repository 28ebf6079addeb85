"""Pass-band and aliasing curves of three filters: two of libsample's and
one written in numpy, measured by the same frequency test (doc/python.md,
doc/frequency-tests.md).

    python3 plot_filters.py [OUT.png]

Left: the response |H| below the pixel Nyquist frequency (ideal: 1).
Right: the leakage above it, which shows up as aliasing (ideal: 0).
"""
import sys

import matplotlib

matplotlib.use("Agg")  # files only; no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import libsample  # noqa: E402


def box4(queries, texture):
    """A 4 x 4 box of base-level texels around the nearest one."""
    lv = texture.level(0)  # (h, w, 4) linear float32
    h, w = lv.shape[:2]
    i = np.floor(queries[:, 0] * w).astype(int)
    j = np.floor(queries[:, 1] * h).astype(int)
    acc = np.zeros((len(queries), 4))
    for dj in range(-2, 2):
        for di in range(-2, 2):
            acc += lv[(j + dj) % h, (i + di) % w]
    return acc / 16


def main(out="filters.png"):
    m = 4.0  # texels per pixel
    res = libsample.freq({"trilinear": "trilinear", "EWA": "ewa", "box 4x4 (numpy)": box4},
                         m=[m], theta=[0.0], n=128, f_step=1 / 32)
    fig, (lo, hi) = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for name in res.filters:
        F, amp, err = res.curve(name, m)
        s = res.summary(name)
        below, above = F <= 0.5, F >= 0.5
        lo.errorbar(F[below], amp[below], yerr=err[below], label="%s (pass %.2f)" % (name, s.pass_band))
        hi.errorbar(F[above], amp[above], yerr=err[above], label="%s (alias %.3f)" % (name, s.aliasing))
    lo.axhline(1.0, color="grey", lw=0.5)
    lo.set(title="pass band", xlabel="F (cycles/pixel)", ylabel="|H|", xlim=(0, 0.5))
    hi.set(title="aliasing (leakage above Nyquist)", xlabel="F (cycles/pixel)", xlim=(0.5, 2.0))
    lo.legend()
    hi.legend()
    fig.tight_layout()
    fig.savefig(out)
    print("wrote", out)


if __name__ == "__main__":
    main(*sys.argv[1:])
