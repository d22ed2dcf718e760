import math, re, sys, itertools
from fractions import Fraction as F

def model(n, kappa, gamma):
    c = [math.cos(2*math.pi*m/n) for m in range(n)]
    s = [math.sin(2*math.pi*m/n) for m in range(n)]
    def ab(k):
        a = -math.sin(2*math.pi*(k-1)/n)/s[1]; b = math.sin(2*math.pi*k/n)/s[1]
        return a, b
    def row(k):
        a, b = ab(k % n); return (a, b, 1-a-b)
    beta = (1+gamma)/(1+kappa)
    d0 = (kappa+1, kappa+c[n-1], kappa)
    def I0(p):
        u0 = p[0]; return tuple(p[i]-beta*u0*d0[i] for i in range(3))
    def R(j, p):
        r0, r1 = row(j), row(j+1)
        return (dot(r0,p), dot(r1,p), p[2])
    def S(j, p): return I0(R(j, p))
    def m(k, l):
        # solve h_k = h_l = 0, hc = 1 for (h0,h1)
        a1,b1,c1 = row(k); a2,b2,c2 = row(l)
        det = a1*b2-a2*b1
        h0 = (-c1*b2 + c2*b1)/det; h1 = (-a1*c2 + a2*c1)/det
        return (h0, h1, 1.0)
    return dict(n=n, row=row, I0=I0, R=R, S=S, m=m)

def dot(a,b): return sum(x*y for x,y in zip(a,b))
def cross(a,b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])

def Cj(M, j):
    n = M['n']; m = M['m']
    return [(1,0,0),(0,0,-1), cross(m(j,(j+1)%n), m(0,1)), cross(m(n-1,0), m(j-1,j))]

def clip(poly, ell):
    # poly: list of 3-vectors with v=-1 (cyclic); keep ell.p >= 0
    out = []
    N = len(poly)
    for i in range(N):
        P, Q = poly[i], poly[(i+1)%N]
        a, b = dot(ell,P), dot(ell,Q)
        if a >= 0: out.append(P)
        if (a >= 0) != (b >= 0):
            t = a/(a-b); out.append(tuple(P[k]+t*(Q[k]-P[k]) for k in range(3)))
    return out

def read_cone(path):
    txt = open(path).read()
    gens = re.findall(r'\("([^"]+)", "([^"]+)", "([^"]+)"\)', txt.split('cone:')[1])
    return [tuple(float(F(x)) for x in g) for g in gens]

def hull_order(gens):
    # order generators (all v=-1) counterclockwise around centroid in (u0,u1)
    cx = sum(g[0] for g in gens)/len(gens); cy = sum(g[1] for g in gens)/len(gens)
    return sorted(gens, key=lambda g: math.atan2(g[1]-cy, g[0]-cx))

def margins(M, K, b):
    n = M['n']; m = M['m']
    # (a) numerator >= 0 on post-impact configs
    pos = min(dot(b, m(0,1)), dot(b, m(n-1,0)))
    # (b) -b.p > 0 on K
    den = min(-dot(b,g) for g in K)
    worst = float('inf')
    for j in range(1, n):
        P = K
        for ell in Cj(M, j):
            P = clip(P, ell)
            if not P: break
        if not P: continue
        for p in P:
            Sp = M['S'](j, p)
            for q in (m(j-1,j), m(j,(j+1)%n)):
                Rq = M['R'](j, q)
                lhs = dot(b,Rq)*(-dot(b,p)); rhs = dot(b,q)*(-dot(b,Sp))
                worst = min(worst, (rhs - lhs)/(abs(rhs)+abs(lhs)+1e-300))
    return pos, den, worst

def search(M, K, steps=400):
    best = None
    for i in range(steps):
        for k in range(steps//2):
            th = 2*math.pi*i/steps; ph = math.pi*(k+0.5)/(steps//2)
            b = (math.sin(ph)*math.cos(th), math.sin(ph)*math.sin(th), math.cos(ph))
            pos, den, w = margins(M, K, b)
            if pos < 0 or den <= 0: continue
            sc = w
            if best is None or sc > best[0]: best = (sc, b, pos, den)
    return best

if __name__ == '__main__':
    n, kap, gam, path = int(sys.argv[1]), float(F(sys.argv[2])), float(F(sys.argv[3])), sys.argv[4]
    M = model(n, kap, gam)
    K = hull_order(read_cone(path))
    print(len(K), 'generators')
    print(search(M, K, int(sys.argv[5]) if len(sys.argv) > 5 else 200))

def inside(K, p, tol=1e-9):
    # p (any scale, v<0) inside polygon K (ccw, v=-1)
    p = tuple(x/(-p[2]) for x in p)
    N = len(K)
    for i in range(N):
        A, B = K[i], K[(i+1)%N]
        cr = (B[0]-A[0])*(p[1]-A[1]) - (B[1]-A[1])*(p[0]-A[0])
        if cr < -tol: return False
    return True

def check_invariance(M, K):
    n = M['n']; bad = 0; tot = 0
    for j in range(1, n):
        P = K
        for ell in Cj(M, j):
            P = clip(P, ell)
            if not P: break
        if not P: continue
        for p in P:
            tot += 1
            if not inside(K, M['S'](j, p)): bad += 1
    return bad, tot

def samples(P, k=12):
    # points in polygon P (v=-1): fan triangulation barycentric grid
    pts = []
    for t in range(1, len(P)-1):
        A, B, C = P[0], P[t], P[t+1]
        for i in range(k+1):
            for l in range(k+1-i):
                a, b = i/k, l/k; c = 1-a-b
                pts.append(tuple(a*A[r]+b*B[r]+c*C[r] for r in range(3)))
    return pts

def margins2(M, K, b, k=8, valid=True):
    n = M['n']; m = M['m']; row = M['row']
    pos = min(dot(b, m(0,1)), dot(b, m(n-1,0)))
    den = min(-dot(b,g) for g in K)
    worst = float('inf')
    for j in range(1, n):
        P = K
        for ell in Cj(M, j):
            P = clip(P, ell)
            if not P: break
        if not P: continue
        for p in samples(P, k):
            uj = dot(row(j), p)
            if uj >= 0: continue
            Sp = M['S'](j, p)
            for s in [i/10 for i in range(11)] if valid else [0, 1]:
                q0 = tuple(s*x+(1-s)*y for x, y in zip(m(0,1), m(n-1,0)))
                f = dot(row(j), q0)/(-uj)
                q = tuple(q0[r]+f*p[r] for r in range(3))
                if valid and any(dot(row(kk), q) < -1e-12 for kk in range(n)): continue
                Rq = M['R'](j, q)
                lhs = dot(b,Rq)*(-dot(b,p)); rhs = dot(b,q)*(-dot(b,Sp))
                worst = min(worst, (rhs - lhs)/(abs(rhs)+abs(lhs)+1e-300))
    return pos, den, worst

def search2(M, K, steps=60, k=6, valid=True):
    best = None
    for i in range(steps):
        for kk in range(steps//2):
            th = 2*math.pi*i/steps; ph = math.pi*(kk+0.5)/(steps//2)
            b = (math.sin(ph)*math.cos(th), math.sin(ph)*math.sin(th), math.cos(ph))
            pos, den, w = margins2(M, K, b, k, valid)
            if pos < 0 or den <= 0: continue
            if best is None or w > best[0]: best = (w, b, pos, den)
    return best

def run(M, q, p, N=3000):
    """From a post-impact state (relabelled so last impact at 0): total flight time (normalised by hc/|v|)."""
    n = M['n']; row = M['row']
    s0 = q[2]/(-p[2]); T = 0.0
    for it in range(N):
        best = None
        for j in range(1, n):
            uj = dot(row(j), p)
            if uj < 0:
                f = dot(row(j), q)/(-uj)
                if best is None or f < best[0]: best = (f, j)
        if best is None: return float('inf'), it, 'ICC'
        f, j = best
        T += f
        q = tuple(q[r]+f*p[r] for r in range(3))
        q = M['R'](j, q); p = M['S'](j, p)
        # renormalise
        sc = q[2]; q = tuple(x/sc for x in q); p = tuple(x/sc for x in p); T_scale = sc
        # keep T in units: time scales with position scale/velocity scale; we scale both by sc, so time unchanged
        if p[2] >= 0: return float('inf'), it, 'ICC'
    return T/s0, N, q[2]/(-p[2])

def attractor(M, p, q, N=300):
    """Iterate from (q,p) N impacts; return list of (j, q, p) post-impact normalised states of the last 20."""
    n = M['n']; row = M['row']; out = []
    for it in range(N):
        best = None
        for j in range(1, n):
            uj = dot(row(j), p)
            if uj < 0:
                f = dot(row(j), q)/(-uj)
                if best is None or f < best[0]: best = (f, j)
        f, j = best
        q = tuple(q[r]+f*p[r] for r in range(3)); q = M['R'](j, q); p = M['S'](j, p)
        sc = -p[2]; p = tuple(x/sc for x in p); q = tuple(x/q[2] for x in q)
        if it >= N-20: out.append((j, q, p))
    return out

def cond_at(M, b, q0, p):
    """Tight transition margin from post-impact (q0,p): Phi_after - Phi_before (<=0 good), and flight."""
    n = M['n']; row = M['row']
    best = None
    for j in range(1, n):
        uj = dot(row(j), p)
        if uj < 0:
            f = dot(row(j), q0)/(-uj)
            if best is None or f < best[0]: best = (f, j)
    f, j = best
    q = tuple(q0[r]+f*p[r] for r in range(3))
    before = dot(b, q)/(-dot(b, p)); Sp = M['S'](j, p); after = dot(b, M['R'](j, q))/(-dot(b, Sp))
    return after - before, j, f

def relaxed_margin(M, b, p, j):
    """max over q in cone(m_{j-1,j}, m_{j,j+1}) of Phi_after - Phi_before (bilinear relaxation), p pre-impact vel."""
    n = M['n']; m = M['m']; worst = -float('inf')
    Sp = M['S'](j, p)
    for q in (m(j-1, j), m(j, (j+1) % n)):
        before = dot(b, q)/(-dot(b, p)); after = dot(b, M['R'](j, q))/(-dot(b, Sp))
        worst = max(worst, after - before)
    return worst

def next_j(M, q, p):
    n = M['n']; row = M['row']; best = None
    for j in range(1, n):
        uj = dot(row(j), p)
        if uj < 0:
            f = dot(row(j), q)/(-uj)
            if best is None or f < best[0]: best = (f, j)
    return best[1]

def sphere(N):
    for i in range(N):
        for k in range(N//2):
            th = 2*math.pi*i/N; ph = math.pi*(k+0.5)/(N//2)
            yield (math.sin(ph)*math.cos(th), math.sin(ph)*math.sin(th), math.cos(ph))
