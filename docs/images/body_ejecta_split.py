# Splits the target's energy gain from the deposit (snapshot at the deposit time -> final) into the
# asteroid's body (particles inside the original 35 m sphere at the deposit time) and the ejecta
# (outside it then). Reads snapshots with h5dump (no h5py here). The asteroid's centre is the
# origin, as in the scenes.
#   python3 docs/images/body_ejecta_split.py RUN/snapshots/snap_AT_BURST.h5 RUN/snapshots/snap_LAST.h5 \
#       YIELD_J TARGET_MATERIAL_INDICES      (e.g. 4.184e14 0,1: granite and rubble)
# docs/asteroid_studies.md used it for the body/above columns of the real-crater tables.
import math, os, subprocess, sys, tempfile

def ds(path, name):
    with tempfile.TemporaryDirectory() as d:
        tmp = os.path.join(d, 'dataset.txt')
        subprocess.run(['h5dump', '-d', '/particles/' + name, '-y', '-w', '0', '-m', '%.17g', '-o', tmp, path],
                       capture_output=True, text=True, check=True)
        return [float(x) for x in open(tmp).read().replace(',', ' ').split()]
def load(path):
    ids = ds(path, 'id'); m = ds(path, 'mass'); u = ds(path, 'internal_energy'); mat = ds(path, 'material')
    x = ds(path, 'position'); v = ds(path, 'velocity')
    P = {}
    for k in range(len(ids)):
        P[int(ids[k])] = (m[k], u[k], int(mat[k]), x[3*k:3*k+3], v[3*k:3*k+3])
    return P
before, after = load(sys.argv[1]), load(sys.argv[2])
yield_J = float(sys.argv[3]); targets = [int(t) for t in sys.argv[4].split(',')]
R = 35.0
gain = {'body': 0.0, 'ejecta': 0.0}
count = {'body': 0, 'ejecta': 0}
for i, (m, u, mat, x, v) in before.items():
    if mat not in targets: continue
    e0 = m * (u + 0.5 * (v[0]**2 + v[1]**2 + v[2]**2))
    m1, u1, _, x1, v1 = after[i]
    e1 = m1 * (u1 + 0.5 * (v1[0]**2 + v1[1]**2 + v1[2]**2))
    where = 'ejecta' if math.hypot(x[0], x[1]) > R else 'body'
    gain[where] += e1 - e0; count[where] += 1
tot = gain['body'] + gain['ejecta']
print(f"share total {tot/yield_J:.4f}  body {gain['body']/yield_J:.4f}  ejecta {gain['ejecta']/yield_J:.4f}  (ejecta particles at the burst: {count['ejecta']})")
