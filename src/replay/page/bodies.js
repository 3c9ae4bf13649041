// The drawn bodies: the peg (solid or section), the hole's block (with a
// cut-away wedge turned towards the viewer, or the section's two walls).
// Every position goes through the radial map of geometry.js.
"use strict";

var Replay = window.Replay || (window.Replay = {});

Replay.COLORS = {
  peg: 0xc5d3e0,
  stripe: 0x2d3e50,
  block: 0xd4d9de,
  cut: 0x8d99a6,
  outline: 0x1d2733,
};

// The peg: body-frame vertices (centre of mass at the origin, axis along
// body z), placed each frame by the pose and the radial map.
Replay.Peg = function (T, g, section) {
  this.T = T;
  var geo = new T.BufferGeometry();
  var body;
  if (section) {
    var poly = Replay.pegSection(g);
    var contour = poly.map(function (p) { return new T.Vector2(p[0], p[1]); });
    var faces = T.ShapeUtils.triangulateShape(contour, []);
    body = new Float32Array(poly.length * 3);
    poly.forEach(function (p, i) {
      body[3 * i] = p[0];
      body[3 * i + 1] = 0;
      body[3 * i + 2] = p[1] - g.centre_height;
    });
    var index = [];
    faces.forEach(function (f) { index.push(f[0], f[1], f[2]); });
    geo.setIndex(index);
    geo.setAttribute("position", new T.BufferAttribute(new Float32Array(body.length), 3));
    this.mesh = new T.Mesh(geo, new T.MeshBasicMaterial({ color: Replay.COLORS.peg, side: T.DoubleSide }));
    var line = new T.BufferGeometry();
    line.setAttribute("position", geo.getAttribute("position"));
    this.outline = new T.LineLoop(line, new T.LineBasicMaterial({ color: Replay.COLORS.outline }));
    this.mesh.add(this.outline);
  } else {
    var rev = Replay.revolve(Replay.pegProfile(g), 0, 2 * Math.PI, 96);
    body = Replay.place(rev.cyl, null);
    var colors = new Float32Array(body.length);
    var peg = new T.Color(Replay.COLORS.peg), stripe = new T.Color(Replay.COLORS.stripe);
    for (var i = 0; i < body.length; i += 3) {
      body[i + 2] -= g.centre_height;
      // A dark stripe along the side shows the spin about the axis.
      var c = rev.cyl[i + 1] < 0.2 ? stripe : peg;
      colors[i] = c.r; colors[i + 1] = c.g; colors[i + 2] = c.b;
    }
    geo.setIndex(rev.index);
    geo.setAttribute("position", new T.BufferAttribute(body.slice(), 3));
    geo.computeVertexNormals();
    this.normals = geo.getAttribute("normal").array.slice();
    geo.setAttribute("color", new T.BufferAttribute(colors, 3));
    this.mesh = new T.Mesh(geo, new T.MeshStandardMaterial({
      vertexColors: true, metalness: 0.1, roughness: 0.5,
    }));
  }
  this.body = body;
  this.geo = geo;
  this._v = new T.Vector3();
};

// Places the peg at centre p (Vector3) with orientation q (Quaternion).
Replay.Peg.prototype.place = function (p, q, f) {
  var pos = this.geo.getAttribute("position");
  var out = pos.array, b = this.body, v = this._v;
  for (var i = 0; i < b.length; i += 3) {
    v.set(b[i], b[i + 1], b[i + 2]).applyQuaternion(q).add(p);
    out[i] = v.x; out[i + 1] = v.y; out[i + 2] = v.z;
  }
  Replay.mapArray(out, f);
  pos.needsUpdate = true;
  if (this.normals) {
    var n = this.geo.getAttribute("normal");
    for (var j = 0; j < b.length; j += 3) {
      v.set(this.normals[j], this.normals[j + 1], this.normals[j + 2]).applyQuaternion(q);
      n.array[j] = v.x; n.array[j + 1] = v.y; n.array[j + 2] = v.z;
    }
    n.needsUpdate = true;
  }
  this.geo.computeBoundingSphere();
  this.geo.computeBoundingBox();
};

// The block: a solid of revolution with the wedge |phi| < cut/2 left out
// (turned towards the viewer by rotating the group about z, which the
// radial map commutes with), the section faces at the wedge's sides; or,
// for a section view, the two walls in the x-z plane.
Replay.Block = function (T, g, section) {
  this.T = T;
  this.g = g;
  this.section = section;
  this.profile = Replay.holeProfile(g);
  this.group = new T.Group();
  this.solid = new T.MeshStandardMaterial({
    color: Replay.COLORS.block, metalness: 0.05, roughness: 0.8, side: T.DoubleSide,
  });
  this.cutMaterial = new T.MeshStandardMaterial({
    color: Replay.COLORS.cut, metalness: 0.1, roughness: 0.9, side: T.DoubleSide,
  });
  this.cut = section ? 0 : Math.PI / 2;
  this.f = null;
};

// The section polygon placed at azimuth phi (a flat mesh).
Replay.Block.prototype.face = function (phi, f, material) {
  var T = this.T, pts = this.profile.points;
  var contour = pts.map(function (p) { return new T.Vector2(p[0], p[1]); });
  var faces = T.ShapeUtils.triangulateShape(contour, []);
  var cyl = [];
  pts.forEach(function (p) { cyl.push(p[0], phi, p[1]); });
  var geo = new T.BufferGeometry();
  geo.setAttribute("position", new T.BufferAttribute(Replay.place(cyl, f), 3));
  var index = [];
  faces.forEach(function (t) { index.push(t[0], t[1], t[2]); });
  geo.setIndex(index);
  geo.computeVertexNormals();
  var mesh = new T.Mesh(geo, material);
  var edge = new T.BufferGeometry();
  edge.setAttribute("position", geo.getAttribute("position"));
  mesh.add(new T.LineLoop(edge, new T.LineBasicMaterial({ color: Replay.COLORS.outline })));
  return mesh;
};

// (Re)builds the meshes for radial map f, cut-away angle `cut` (radians,
// 0 for none) and glass (see-through) or not.
Replay.Block.prototype.build = function (f, cut, glass) {
  var T = this.T;
  this.group.children.slice().forEach(function (c) {
    c.traverse(function (o) { if (o.geometry) o.geometry.dispose(); });
  });
  this.group.clear();
  this.solid.transparent = glass;
  this.solid.opacity = glass ? 0.28 : 1;
  this.solid.depthWrite = !glass;
  this.cutMaterial.transparent = glass;
  this.cutMaterial.opacity = glass ? 0.4 : 1;
  if (this.section) {
    this.group.add(this.face(0, f, this.cutMaterial));
    this.group.add(this.face(Math.PI, f, this.cutMaterial));
    return;
  }
  var half = cut / 2;
  var rev = Replay.revolve(this.profile.points, half, 2 * Math.PI - half, 120);
  var geo = new T.BufferGeometry();
  geo.setAttribute("position", new T.BufferAttribute(Replay.place(rev.cyl, f), 3));
  geo.setIndex(rev.index);
  geo.computeVertexNormals();
  this.group.add(new T.Mesh(geo, this.solid));
  if (cut > 0) {
    this.group.add(this.face(half, f, this.cutMaterial));
    this.group.add(this.face(-half, f, this.cutMaterial));
  }
};
