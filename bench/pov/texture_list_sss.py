#!/usr/bin/env python3
# texture_list_sss.py OUTDIR: writes one.pov and two.pov, a closed icosphere (320 faces) in the same
# wax, with one texture and with a texture_list of two (x < 0 and x >= 0); bench/README.md,
# "texture_list pieces and SSS" (light19b). circe renders them: the images must match.
import math, os, sys
# an icosphere (closed), subdivided twice
t=(1+5**.5)/2
V=[(-1,t,0),(1,t,0),(-1,-t,0),(1,-t,0),(0,-1,t),(0,1,t),(0,-1,-t),(0,1,-t),(t,0,-1),(t,0,1),(-t,0,-1),(-t,0,1)]
F=[(0,11,5),(0,5,1),(0,1,7),(0,7,10),(0,10,11),(1,5,9),(5,11,4),(11,10,2),(10,7,6),(7,1,8),(3,9,4),(3,4,2),(3,2,6),(3,6,8),(3,8,9),(4,9,5),(2,4,11),(6,2,10),(8,6,7),(9,8,1)]
V=[tuple(c/math.sqrt(sum(x*x for x in v)) for c in v) for v in V]
for _ in range(2):
    cache={}; NF=[]
    def mid(a,b):
        k=(min(a,b),max(a,b))
        if k not in cache:
            m=[(V[a][i]+V[b][i])/2 for i in range(3)]; l=math.sqrt(sum(x*x for x in m))
            V.append(tuple(x/l for x in m)); cache[k]=len(V)-1
        return cache[k]
    for a,b,c in F:
        ab,bc,ca=mid(a,b),mid(b,c),mid(c,a)
        NF+= [(a,ab,ca),(b,bc,ab),(c,ca,bc),(ab,bc,ca)]
    F=NF
def mesh(two):
    out=["mesh2 { vertex_vectors { %d, %s }"%(len(V), ", ".join("<%.6f,%.6f,%.6f>"%v for v in V))]
    if two: out.append(" texture_list { 2, texture { Wax }, texture { Wax } }")
    fs=[]
    for a,b,c in F:
        cx=V[a][0]+V[b][0]+V[c][0]
        fs.append("<%d,%d,%d>%s"%(a,b,c, (", %d"%(0 if cx<0 else 1)) if two else ""))
    out.append(" face_indices { %d, %s }"%(len(F), ", ".join(fs)))
    if not two: out.append(" texture { Wax }")
    out.append("}")
    return "\n".join(out)

HEAD = """global_settings { mm_per_unit 10 }
camera { location <0, 0.5, -3.2> look_at 0 angle 40 }
light_source { <-1, 3, 2> color 1.5 }
light_source { <0, 1, -4> color 0.4 }
plane { y, -1 pigment { rgb 0.5 } }
#declare Wax = material { wax { radius <4, 3, 2> } }
"""
out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)
for name, two in (("one", False), ("two", True)):
    with open(os.path.join(out, name + ".pov"), "w") as f:
        f.write(HEAD + mesh(two) + "\n")
