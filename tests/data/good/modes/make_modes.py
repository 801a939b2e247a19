import json, struct, base64, math
# Strip: alternating top and bottom of a band in the plane z = 0, the first triangle facing +Z.
strip = [(0,1,0),(0,0,0),(0.8,1.1,0),(0.7,0,0),(1.5,0.9,0),(1.9,0,0)]
# Fan: the centre, then an arc counter-clockwise seen from +Z, in the plane z = 1.
fan = [(3,0,1)] + [(round(3+math.cos(a),6), round(math.sin(a),6), 1) for a in [0.0, 0.7, 1.5, 2.4, 3.1]]
def buf(data): return "data:application/octet-stream;base64," + base64.b64encode(data).decode()
def f32(vs): return b"".join(struct.pack("<3f", *v) for v in vs)
def u16(ix):
    b = b"".join(struct.pack("<H", i) for i in ix)
    return b + b"\0"*(-len(b)%4)
def bounds(vs):
    vs=[struct.unpack("<3f",struct.pack("<3f",*v)) for v in vs]
    return [min(v[k] for v in vs) for k in range(3)], [max(v[k] for v in vs) for k in range(3)]
order = [3,0,5,1,4,2]             # the strip's vertex buffer holds strip[order]; its indices draw strip[0..5]
vbuf = [strip[i] for i in order]
sidx = [order.index(k) for k in range(6)]
def doc(prims, accessors, views, buffers):
    return {"asset":{"version":"2.0","generator":"hand-written for vkphoton's tests (tests/data/good/modes)"},
            "scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":prims}],
            "materials":[{"name":"lamp","emissiveFactor":[1,1,1]}],
            "accessors":accessors,"bufferViews":views,"buffers":buffers}
def acc(view, count, typ, comp, vs=None):
    a={"bufferView":view,"componentType":comp,"count":count,"type":typ}
    if vs: a["min"],a["max"]=bounds(vs)
    return a
b0 = f32(vbuf); b1 = u16(sidx); b2 = f32(fan)
modes = doc([{"attributes":{"POSITION":0},"indices":1,"mode":5,"material":0},
             {"attributes":{"POSITION":2},"mode":6,"material":0}],
            [acc(0,6,"VEC3",5126,vbuf), acc(1,6,"SCALAR",5123), acc(2,6,"VEC3",5126,fan)],
            [{"buffer":0,"byteLength":len(b0)},{"buffer":1,"byteLength":12},{"buffer":2,"byteLength":len(b2)}],
            [{"byteLength":len(b0),"uri":buf(b0)},{"byteLength":len(b1),"uri":buf(b1)},{"byteLength":len(b2),"uri":buf(b2)}])
json.dump(modes, open("strip_fan.gltf","w"), indent=1)
# The same triangles as TRIANGLES, written out from the specification's table (glTF 2.0, 3.7.2.1):
# strip i = (v_i, v_{i+1+i%2}, v_{i+2-i%2}), fan i = (v_{i+1}, v_{i+2}, v_0).
s, f = strip, fan
tri_strip = [s[0],s[1],s[2], s[1],s[3],s[2], s[2],s[3],s[4], s[3],s[5],s[4]]
tri_fan = [f[1],f[2],f[0], f[2],f[3],f[0], f[3],f[4],f[0], f[4],f[5],f[0]]
c0 = f32(tri_strip); c1 = f32(tri_fan)
tris = doc([{"attributes":{"POSITION":0},"mode":4,"material":0},
            {"attributes":{"POSITION":1},"material":0}],
           [acc(0,12,"VEC3",5126,tri_strip), acc(1,12,"VEC3",5126,tri_fan)],
           [{"buffer":0,"byteLength":len(c0)},{"buffer":1,"byteLength":len(c1)}],
           [{"byteLength":len(c0),"uri":buf(c0)},{"byteLength":len(c1),"uri":buf(c1)}])
json.dump(tris, open("strip_fan_as_triangles.gltf","w"), indent=1)
def cross(a,b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
for L in (tri_strip, tri_fan):
    for i in range(0,len(L),3):
        p,q,r=L[i:i+3]; n=cross([q[k]-p[k] for k in range(3)],[r[k]-p[k] for k in range(3)]); print(round(n[2],3), end=" ")
print()
