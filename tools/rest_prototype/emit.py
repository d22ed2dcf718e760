"""Untrusted producer of a virtual-time graph (docs/time-to-rest.md §5) for n = 3, 4, 6: the
float graph and weights of graph.py / weights.py, then exact rationals (Fractions), an exact
check of (G1)-(G5) written from the docs, and the RON file the kernel checks.

    python3 tools/rest_prototype/emit.py 4 1/6 1/100 OUT.ron
"""
import sys, os, math
sys.path.insert(0, os.path.dirname(__file__))
from fractions import Fraction as F
from lyap import model, dot
from graph import build, hull, clip
from weights import choose, ratio, admissible, sphere, refine

COS = {3: [F(1), F(-1, 2), F(-1, 2)], 4: [F(1), F(0), F(-1), F(0)],
       6: [F(1), F(1, 2), F(-1, 2), F(-1), F(-1, 2), F(1, 2)]}

def exact_model(n, kappa, gamma):
    c1 = COS[n][1]
    U = {-2: F(-1), -1: F(0)}
    for m in range(0, n + 2): U[m] = 2 * c1 * U[m - 1] - U[m - 2]
    def row(k):
        k %= n; a, b = -U[k - 2], U[k - 1]; return (a, b, 1 - a - b)
    beta = (1 + gamma) / (1 + kappa)
    d0 = (kappa + 1, kappa + COS[n][n - 1], kappa)
    def I0(p): return tuple(p[i] - beta * p[0] * d0[i] for i in range(3))
    def R(j, p): return (dot(row(j), p), dot(row(j + 1), p), p[2])
    def S(j, p): return I0(R(j, p))
    def m(k, l):
        a1, b1, c1_ = row(k); a2, b2, c2 = row(l); det = a1 * b2 - a2 * b1
        return ((-c1_ * b2 + c2 * b1) / det, (-a1 * c2 + a2 * c1_) / det, F(1))
    def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
    def Cj(j): return [(1, 0, 0), (0, 0, -1), cross(m(j, (j+1) % n), m(0, 1)), cross(m(n-1, 0), m(j-1, j))]
    return dict(n=n, row=row, I0=I0, R=R, S=S, m=m, Cj=Cj)

def xclip(poly, ell):
    out = []; N = len(poly)
    for i in range(N):
        P, Q = poly[i], poly[(i + 1) % N]; a, b = dot(ell, P), dot(ell, Q)
        if a >= 0: out.append(P)
        if (a > 0 and b < 0) or (a < 0 and b > 0):
            out.append(tuple(a * Q[k] - b * P[k] for k in range(3)))  # (l.P) Q - (l.Q) P, positive
    return [tuple(x / -p[2] for x in p) for p in out]

def xinside(K, p):
    p = tuple(x / -p[2] for x in p); N = len(K)
    return p[2] == -1 and all((K[(i+1)%N][0]-K[i][0])*(p[1]-K[i][1]) - (K[(i+1)%N][1]-K[i][1])*(p[0]-K[i][0]) >= 0 for i in range(N))

def rat(x, den=2**24): return F(round(x * den), den)

def inv3(A):
    a,b,c=A[0];d,e,f=A[1];g,h,i=A[2]
    det=a*(e*i-f*h)-b*(d*i-f*g)+c*(d*h-e*g)
    return [[(e*i-f*h)/det,(c*h-b*i)/det,(b*f-c*e)/det],[(f*g-d*i)/det,(a*i-c*g)/det,(c*d-a*f)/det],[(d*h-e*g)/det,(b*g-a*h)/det,(a*e-b*d)/det]]

def covec(b, A): return tuple(sum(b[r] * A[r][c] for r in range(3)) for c in range(3))

def Rmat(X, j):
    cols = [X['R'](j, e) for e in ((1,0,0),(0,1,0),(0,0,1))]
    return [[cols[c][r] for c in range(3)] for r in range(3)]

def check(X, nodes, bound):
    """(G1)-(G5) exactly; returns a list of failures (empty when the graph is valid)."""
    n, m = X['n'], X['m']; bad = []
    for r, nd in enumerate(nodes):
        b, c = nd['weight'], nd['scale']
        if c < 1: bad.append(('scale', r))
        if any(g[2] >= 0 or -dot(b, g) <= 0 for g in nd['cone']): bad.append(('G1', r))
        if dot(b, m(0, 1)) < 0 or dot(b, m(n-1, 0)) < 0: bad.append(('G2', r))
        for j in range(1, n):
            P = nd['cone']
            for ell in X['Cj'](j):
                P = xclip(P, ell)
                if not P: break
            if not P: continue
            if j not in nd['next']: bad.append(('next', r, j)); continue
            s = nd['next'][j]; bs, cs = nodes[s]['weight'], nodes[s]['scale']
            for p in P:
                Sp = X['S'](j, p)
                if any(x != 0 for x in Sp) and not xinside(nodes[s]['cone'], Sp): bad.append(('G3 image', r, j))
                for q in (m(j-1, j), m(j, (j+1) % n)):
                    if cs * dot(bs, X['R'](j, q)) * -dot(b, p) > c * dot(b, q) * -dot(bs, Sp):
                        bad.append(('G3 time', r, j, s))
    b0, c0 = nodes[0]['weight'], nodes[0]['scale']
    for k in range(n):
        g = tuple(-x for x in m(k, (k+1) % n)); ig = X['I0'](g)
        if not xinside(nodes[0]['cone'], ig): bad.append(('G4', k))
        for mm in (m(0, 1), m(n-1, 0)):
            if bound * -dot(b0, ig) < c0 * dot(b0, mm): bad.append(('G5', k))
    return bad

def components(M, edges, R):
    """Nodes linked both ways by j and n - j (two adjacent contacts alternating) share one covector
    up to relabelling, b_s = b_r R_j^{-1}, and one scale (docs/time-to-rest.md §5)."""
    n = M['n']; I3 = [[1,0,0],[0,1,0],[0,0,1]]
    rep = list(range(R)); T = [I3] * R; adj = {}
    for (r, j), (s, P) in edges.items():
        if s != r and edges.get((s, n - j), (None,))[0] == r:
            adj.setdefault(r, []).append((s, j))
    seen = [False] * R
    for r0 in range(R):
        if seen[r0]: continue
        seen[r0] = True; stack = [r0]
        while stack:
            r = stack.pop()
            for s, j in adj.get(r, []):
                if not seen[s]:
                    seen[s] = True; rep[s] = r0; T[s] = (T[r], j); stack.append(s)
    return rep, T

def transform(X, T, b):
    """b_s from the representative's covector along the chain of relabellings T."""
    if not isinstance(T, tuple): return b
    prev, j = T
    return covec(transform(X, prev, b), inv3(Rmat(X, j)))

def weights(M, X, nodes, edges, rounds=12, N=40, eta=1e-3):
    R = len(nodes); rep, T = components(M, edges, R)
    comps = {}
    for r in range(R): comps.setdefault(rep[r], []).append(r)
    b0s = choose(M, nodes, edges, N)
    B = {k: b0s[k] for k in comps}; c = {k: 1.0 for k in comps}
    fl = lambda v: tuple(float(x) for x in v)
    def bof(r): return fl(transform(X, T[r], tuple(F(x) for x in B[rep[r]])))
    outs = list(edges.items())
    for it in range(rounds):
        delta = 0
        for k in sorted(comps, reverse=True):
            mem = comps[k]
            def req(b):
                old = B[k]; B[k] = b
                try:
                    if not all(admissible(M, bof(r), nodes[r]) for r in mem): return float('inf')
                    v = 1.0
                    for (r, j), (s, P) in outs:
                        if rep[r] != k: continue
                        g = ratio(M, bof(r), bof(s), j, P)
                        if rep[s] == k:
                            if g > 1 + 1e-12: return 1e6 * g
                        else: v = max(v, g * (1 + eta) * c[rep[s]])
                    return v
                finally: B[k] = old
            b1 = min(list(sphere(N)) + [B[k]], key=req); b, s = refine(M, req, b1, 40)
            if s < float('inf'):
                delta = max(delta, abs(s - c[k]) / c[k]); B[k] = b; c[k] = s
        if delta < 1e-12: break
    return rep, T, B, c

def emit(n, kappa, gamma, out, d=0.3):
    M = model(n, float(kappa), float(gamma)); X = exact_model(n, kappa, gamma)
    nodes, edges, ok = build(M, d)
    if not ok: sys.exit(f'the graph did not close within 200 nodes ({len(nodes)} nodes)')
    rep, T, B, c = weights(M, X, nodes, edges)
    exact = []
    for r, nd in enumerate(nodes):
        cone = [(rat(p[0]), rat(p[1]), F(-1)) for p in nd]
        brep = tuple(rat(x / max(abs(y) for y in B[rep[r]])) for x in B[rep[r]])
        b = transform(X, T[r], brep)
        scale = F(math.ceil(c[rep[r]] * (1 + 1e-6) * 2**20), 2**20)
        nxt = {j: s for (rr, j), (s, P) in edges.items() if rr == r}
        exact.append(dict(cone=cone, weight=b, scale=scale, next=nxt))
    b0, c0, m = exact[0]['weight'], exact[0]['scale'], X['m']
    need = max(c0 * dot(b0, mm) / -dot(b0, X['I0'](tuple(-x for x in m(k, (k+1) % n))))
               for k in range(n) for mm in (m(0, 1), m(n-1, 0)))
    bound = F(math.ceil(need * 2**20), 2**20)
    bad = check(X, exact, bound)
    if bad: sys.exit(f'exact check failed: {bad[:10]} ({len(bad)} in all)')
    write(out, n, kappa, gamma, bound, exact)
    print(f'{len(exact)} nodes, bound B = {bound} = {float(bound):.6g}')

def q(x): return f'"{x.numerator}"' if x.denominator == 1 else f'"{x.numerator}/{x.denominator}"'

def write(out, n, kappa, gamma, bound, nodes):
    L = ['TimeToRest(', '    format: "chatter-time-to-rest",', '    version: 1,',
         f'    body: RegularPolygon(n: {n}, kappa: {q(kappa)}, gamma: {q(gamma)}),',
         '    coordinates: ContactVelocities,', '    claim: CompleteChatterFromAllDown,',
         f'    bound: {q(bound)},', '    nodes: [']
    for nd in nodes:
        L.append('        (')
        L.append('            cone: [' + ', '.join('(' + ', '.join(q(x) for x in g) + ')' for g in nd['cone']) + '],')
        L.append('            weight: (' + ', '.join(q(x) for x in nd['weight']) + '),')
        L.append(f'            scale: {q(nd["scale"])},')
        L.append('            next: [' + ', '.join(f'({j}, {s})' for j, s in sorted(nd['next'].items())) + '],')
        L.append('        ),')
    L += ['    ],', '    producer: "tools/rest_prototype/emit.py (untrusted, f64 search, exact rationals)",', ')']
    open(out, 'w').write('\n'.join(L) + '\n')

if __name__ == '__main__':
    emit(int(sys.argv[1]), F(sys.argv[2]), F(sys.argv[3]), sys.argv[4])
