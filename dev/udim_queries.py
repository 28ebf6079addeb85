# Query files for `texsample lookup` (float32 s t ds/dx dt/dx ds/dy dt/dy),
# for dev/udim_timing.sh. KIND: bilinear (footprint 0.8 texel of level 0),
# trilo / trihi (isotropic, lambda uniform in [0, 4] / [4, 8]), aniso (16:1
# ellipses, minor axis 1 to 4 texels, any angle). SCALE 1: queries in [0, 1]
# for one file; 2: in [0, 2], derivatives doubled, for a 2 x 2 UDIM set (the
# same texel footprints on its virtual texture). SIZE: the texture's side.
#   python3 dev/udim_queries.py KIND N SCALE SIZE OUT
import array, math, random, sys

kind, n, scale, size, out = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
random.seed(1)
a = array.array('f')
for _ in range(n):
    s, t = random.random(), random.random()
    if kind == 'bilinear':
        d = 0.8 / size
        ax, ay, bx, by = d, 0.0, 0.0, d
    elif kind in ('trilo', 'trihi'):
        d = 2 ** random.uniform(0 if kind == 'trilo' else 4, 4 if kind == 'trilo' else 8) / size
        ax, ay, bx, by = d, 0.0, 0.0, d
    else:
        minor, th = 2 ** random.uniform(0, 2) / size, random.uniform(0, math.pi)
        ax, ay = 16 * minor * math.cos(th), 16 * minor * math.sin(th)
        bx, by = -minor * math.sin(th), minor * math.cos(th)
    a.extend([s * scale, t * scale, ax * scale, ay * scale, bx * scale, by * scale])
open(out, 'wb').write(a.tobytes())
