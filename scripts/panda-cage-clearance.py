#!/usr/bin/env python3
"""How much fatter is the project's Panda (robots/panda/panda.urdf, 380 spheres) than VAMP's 59-sphere model
(../shared/robots/panda/panda_spherized.urdf) against the Sphere-Search cage? For random configurations within the
joint limits: the distance from each cage sphere's centre to the arm's surface (links past panda_link0) in both
models, and the share of configurations colliding with the cage at several radii. Pure Python (no numpy).

usage: scripts/panda-cage-clearance.py robots/panda/panda.urdf ../shared/robots/panda/panda_spherized.urdf SEED N
"""
import xml.etree.ElementTree as ET, math, random, sys
def rpy(r,p,y):
    cr,sr,cp,sp,cy,sy=math.cos(r),math.sin(r),math.cos(p),math.sin(p),math.cos(y),math.sin(y)
    return [[cy*cp, cy*sp*sr-sy*cr, cy*sp*cr+sy*sr],[sy*cp, sy*sp*sr+cy*cr, sy*sp*cr-cy*sr],[-sp, cp*sr, cp*cr]]
def mm(A,B): return [[sum(A[i][k]*B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
def mv(A,v): return [sum(A[i][k]*v[k] for k in range(3)) for i in range(3)]
def tf(T,U): R=mm(T[0],U[0]); t=[a+b for a,b in zip(mv(T[0],U[1]),T[1])]; return (R,t)
def axrot(ax,q):
    x,y,z=ax; c,s=math.cos(q),math.sin(q); C=1-c
    return [[c+x*x*C, x*y*C-z*s, x*z*C+y*s],[y*x*C+z*s, c+y*y*C, y*z*C-x*s],[z*x*C-y*s, z*y*C+x*s, c+z*z*C]]
def load(path):
    import re; root=ET.fromstring(re.sub(r'<!--.*?-->','',open(path).read(),flags=re.S).split('?>',1)[-1])
    spheres={}
    for l in root.findall('link'):
        for c in l.findall('collision'):
            s=c.find('geometry/sphere')
            if s is None: continue
            o=c.find('origin'); xyz=[float(v) for v in (o.get('xyz','0 0 0').split() if o is not None else [0,0,0])]
            spheres.setdefault(l.get('name'),[]).append((xyz,float(s.get('radius'))))
    joints=[]
    for j in root.findall('joint'):
        o=j.find('origin'); xyz=[float(v) for v in o.get('xyz','0 0 0').split()]; r=[float(v) for v in o.get('rpy','0 0 0').split()]
        ax=j.find('axis'); ax=[float(v) for v in ax.get('xyz').split()] if ax is not None else [0,0,1]
        lim=j.find('limit')
        joints.append(dict(name=j.get('name'),type=j.get('type'),parent=j.find('parent').get('link'),child=j.find('child').get('link'),T=(rpy(*r),xyz),axis=ax,
          lo=float(lim.get('lower')) if lim is not None and lim.get('lower') else 0, hi=float(lim.get('upper')) if lim is not None and lim.get('upper') else 0))
    return spheres,joints
def world_spheres(model,q):
    spheres,joints=model
    T={'panda_link0':([[1,0,0],[0,1,0],[0,0,1]],[0,0,0])}
    k=0; out=[]
    for j in joints:  # URDF order is parent-first here
        if j['parent'] not in T: continue
        U=j['T']
        if j['type'] in ('revolute','continuous'):
            if k < 7: U=tf(U,(axrot(j['axis'],q[k]),[0,0,0]))
            k+=1
        T[j['child']]=tf(T[j['parent']],U)
    for l,ss in spheres.items():
        if l not in T: continue
        R,t=T[l]
        for c,r in ss: out.append(([a+b for a,b in zip(mv(R,c),t)],r,l))
    return out
proj=load(sys.argv[1]); vamp=load(sys.argv[2])
lims=[(j['lo'],j['hi']) for j in proj[1] if j['type']=='revolute'][:7]
cage=[(0.55,0,0.25),(0.35,0.35,0.25),(0.35,-0.35,0.25),(0,0.55,0.25),(0,-0.55,0.25),(-0.55,0,0.25),(-0.35,-0.35,0.25),
(0.35,0.35,0.8),(0.35,-0.35,0.8),(0,0.55,0.8),(0,-0.55,0.8),(-0.35,0.35,0.8),(-0.35,-0.35,0.8),(-0.55,0,0.8)]
random.seed(int(sys.argv[3]) if len(sys.argv)>3 else 1)
diffs=[]; coll={}
N=int(sys.argv[4]) if len(sys.argv)>4 else 400
for it in range(N):
    q=[random.uniform(a,b) for a,b in lims]
    dp=world_spheres(proj,q); dv=world_spheres(vamp,q)
    def clear(ws,o):  # distance from obstacle centre to the arm's surface, links beyond link0/1 only (the base cannot move)
        return min(math.dist(c,o)-r for c,r,l in ws if l not in ('panda_link0',))
    for o in cage:
        cp=clear(dp,o); cv=clear(dv,o)
        if cv < 0.35: diffs.append(cv-cp)
        for rad in (0.14,0.15,0.16,0.17,0.18,0.2):
            coll.setdefault(('p',rad),0); coll.setdefault(('v',rad),0)
    # collision of whole configuration
    for rad in (0.14,0.15,0.16,0.17,0.18,0.2):
        coll[('p',rad)]+= any(clear(dp,o)<rad for o in cage)
        coll[('v',rad)]+= any(clear(dv,o)<rad for o in cage)
diffs.sort()
n=len(diffs)
print("sphere counts", sum(len(v) for v in proj[0].values()), sum(len(v) for v in vamp[0].values()))
print("obstacle-arm clearance, VAMP minus project (m), over", n, "pairs within 0.35 m: median %.4f  p10 %.4f  p90 %.4f  mean %.4f"%(diffs[n//2],diffs[n//10],diffs[9*n//10],sum(diffs)/n))
for rad in (0.14,0.15,0.16,0.17,0.18,0.2):
    print("cage r %.2f: configurations in collision (obstacles only): project %.3f  VAMP %.3f"%(rad,coll[('p',rad)]/N,coll[('v',rad)]/N))
