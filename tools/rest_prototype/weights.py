import sys, math
sys.path.insert(0, __import__("os").path.dirname(__file__))
from lyap import *
from graph import *

def phi(b, q, p): return dot(b, q)/(-dot(b, p))

def ratio(M, br, bt, j, P):
    n = M['n']; m = M['m']; worst = 0.0
    for p in P:
        Sp = M['S'](j, p)
        if -dot(bt, Sp) <= 0 or -dot(br, p) <= 0: return float('inf')
        for q in (m(j-1, j), m(j, (j+1) % n)):
            a = phi(bt, M['R'](j, q), Sp); b0 = phi(br, q, p)
            if a <= 1e-15 and b0 <= 1e-15: continue
            if b0 <= 1e-15: return float('inf')
            worst = max(worst, a/b0)
    return worst

def admissible(M, b, N):
    n = M['n']
    return min(dot(b, M['m'](0, 1)), dot(b, M['m'](n-1, 0))) > 1e-9 and all(-dot(b, g) > 1e-6 for g in N)

def refine(M, score, b0, steps=60):
    b = b0; s = score(b); h = 0.2
    for _ in range(steps):
        improved = False
        for d in [(1,0,0),(-1,0,0),(0,1,0),(0,-1,0),(0,0,1),(0,0,-1)]:
            c = tuple(b[i]+h*d[i] for i in range(3)); nn = math.sqrt(dot(c,c)); c = tuple(x/nn for x in c)
            sc = score(c)
            if sc < s: b, s, improved = c, sc, True
        if not improved: h /= 2
    return b, s

def choose(M, nodes, edges, N=60):
    bs = []
    for r, Nd in enumerate(nodes):
        outs = [(j, t, P) for (rr, j), (t, P) in edges.items() if rr == r]
        def score(b):
            if not admissible(M, b, Nd): return float('inf')
            return max([ratio(M, b, b, j, P) for j, t, P in outs] or [0.0])
        best = min(sphere(N), key=score)
        bs.append(refine(M, score, best)[0])
    return bs

def cycles(nodes, edges, g):
    """c_r = sup over paths from r of the product of g along the path (>=1); None if a cycle has product > 1."""
    R = len(nodes); c = [1.0]*R
    for it in range(R+2):
        ch = False
        for (r, j), (t, P) in edges.items():
            v = g[(r, j)]*c[t]
            if v > c[r]*(1+1e-12): c[r] = v; ch = True
        if not ch: return c
    return None

if __name__ == '__main__':
    n, k, gm = int(sys.argv[1]), float(F(sys.argv[2])), float(F(sys.argv[3]))
    M = model(n, k, gm)
    nodes, edges, ok = build(M, float(sys.argv[4]) if len(sys.argv) > 4 else 0.3)
    print('graph', ok, len(nodes), len(edges))
    bs = choose(M, nodes, edges)
    g = {(r, j): ratio(M, bs[r], bs[t], j, P) for (r, j), (t, P) in edges.items()}
    for (r, j), v in sorted(g.items()): print(r, j, '->', edges[(r, j)][0], round(v, 4))
    c = cycles(nodes, edges, g)
    print('c', c and [round(x, 3) for x in c])
    if c:
        b = bs[0]; m = M['m']
        beta = max(dot(b, m(0,1)), dot(b, m(n-1,0)))
        cmin = min(-dot(b, M['I0'](tuple(-x for x in m(kk, (kk+1) % n)))) for kk in range(n))
        print('B =', c[0]*beta/cmin)

def joint(M, nodes, edges, rounds=30, N=48):
    R = len(nodes); c = [1.0]*R
    bs = choose(M, nodes, edges, N)
    outs = {r: [(j, t, P) for (rr, j), (t, P) in edges.items() if rr == r] for r in range(R)}
    for it in range(rounds):
        changed = 0.0
        for r in reversed(range(R)):
            def score(b):
                if not admissible(M, b, nodes[r]): return float('inf')
                return max([ratio(M, b, b if t == r else bs[t], j, P)*(1.0 if t == r else c[t]) / (1.0 if t != r else 1.0) for j, t, P in outs[r]] or [0.0])
            # self-loops: need ratio <= 1; fold as: required c_r = max over non-self edges g*c_t, provided self g <= 1
            def req(b):
                if not admissible(M, b, nodes[r]): return float('inf')
                v = 1.0
                for j, t, P in outs[r]:
                    gg = ratio(M, b, b if t == r else bs[t], j, P)
                    if t == r:
                        if gg > 1: return float('inf') if gg == float('inf') else 1e6*gg
                    else: v = max(v, gg*c[t])
                return v
            cand = min(list(sphere(N)) + [bs[r]], key=req)
            b, s = refine(M, req, cand, 40)
            if s < float('inf'):
                changed = max(changed, abs(s - c[r])/max(c[r], 1)); bs[r] = b; c[r] = s
        if changed < 1e-9: break
    # final check
    g = {(r, j): ratio(M, bs[r], bs[t], j, P) for (r, j), (t, P) in edges.items()}
    return bs, cycles(nodes, edges, g), g
