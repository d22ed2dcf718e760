import sys, math
sys.path.insert(0, __import__("os").path.dirname(__file__))
from lyap import *

def norm(p): return tuple(x/(-p[2]) for x in p)

def hull(pts):
    pts = sorted(set((round(p[0], 15), round(p[1], 15)) for p in pts))
    if len(pts) <= 2: return [(x, y, -1.0) for x, y in pts]
    def cr(o, a, b): return (a[0]-o[0])*(b[1]-o[1]) - (a[1]-o[1])*(b[0]-o[0])
    lo, up = [], []
    for p in pts:
        while len(lo) >= 2 and cr(lo[-2], lo[-1], p) <= 0: lo.pop()
        lo.append(p)
    for p in reversed(pts):
        while len(up) >= 2 and cr(up[-2], up[-1], p) <= 0: up.pop()
        up.append(p)
    return [(x, y, -1.0) for x, y in lo[:-1] + up[:-1]]

EPS = 1e-3
def enlarge(P, d):
    """The hull of P scaled by 1 + d about its centroid, plus a square of half-side EPS at each
    vertex, so that images contained in it stay contained after rounding to rationals."""
    cx = sum(p[0] for p in P)/len(P); cy = sum(p[1] for p in P)/len(P)
    pts = [(cx+(p[0]-cx)*(1+d)+sx*EPS, cy+(p[1]-cy)*(1+d)+sy*EPS, -1.0) for p in P for sx in (-1, 1) for sy in (-1, 1)]
    return hull(pts)

def contains(K, P, tol=1e-12):
    return all(inside(K, p, -tol) for p in P)

def area(P):
    return 0.5*abs(sum(P[i][0]*P[(i+1)%len(P)][1]-P[(i+1)%len(P)][0]*P[i][1] for i in range(len(P))))

def build(M, d=0.3, maxnodes=200, clip_u0=False):
    n = M['n']
    K0 = hull([norm(M['I0'](tuple(-x for x in M['m'](k, (k+1) % n)))) for k in range(n)])
    nodes = [enlarge(K0, 0.0)]; edges = {}; todo = [0]
    while todo:
        r = todo.pop(0)
        for j in range(1, n):
            P = nodes[r]
            for ell in Cj(M, j):
                P = clip(P, ell)
                if len(P) < 3: break
            if len(P) < 3: continue
            img = hull([norm(M['S'](j, p)) for p in P])
            tgt = None
            for s, N in enumerate(nodes):
                if contains(N, img): 
                    if tgt is None or area(N) < area(nodes[tgt]): tgt = s
            if tgt is None:
                if len(nodes) >= maxnodes: return nodes, edges, False
                new = enlarge(img, d)
                nodes.append(clip(new, (1.0, 0.0, 0.0)) if clip_u0 else new); tgt = len(nodes)-1; todo.append(tgt)
            edges[(r, j)] = (tgt, P)
    return nodes, edges, True

if __name__ == '__main__':
    n, k, g = int(sys.argv[1]), float(F(sys.argv[2])), float(F(sys.argv[3]))
    M = model(n, k, g)
    nodes, edges, ok = build(M, float(sys.argv[4]) if len(sys.argv) > 4 else 0.3, clip_u0=len(sys.argv) > 5)
    print(ok, len(nodes), 'nodes', len(edges), 'edges')
    for r, N in enumerate(nodes): print(r, round(area(N), 6), [(j, edges[(r, j)][0]) for j in range(1, n) if (r, j) in edges])
