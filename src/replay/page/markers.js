// What is drawn over the bodies: contact points with their normal and
// friction force arrows (seen through the walls), the wrist's compliance
// centre and the robot frame, the tip's path and the arrows' scale.
"use strict";

var Replay = window.Replay || (window.Replay = {});

Replay.PAIR_COLORS = [0xe4572e, 0x17a2b8, 0xe0a800, 0x4caf50, 0x9c27b0, 0xff7f0e];
Replay.FRICTION_COLOR = 0x222222;

// Materials drawn on top of the bodies (no depth test): contacts inside
// the bore stay visible from any side.
function overlay(T, color) {
  return new T.MeshBasicMaterial({ color: color, depthTest: false, transparent: true });
}

// An arrow of two meshes (shaft and head) along +y of its group, drawn on
// top of the bodies.
function Arrow(T, color, shaft, head) {
  var m = overlay(T, color);
  this.material = m;
  this.group = new T.Group();
  this.shaft = new T.Mesh(shaft, m);
  this.head = new T.Mesh(head, m);
  this.shaft.renderOrder = this.head.renderOrder = 10;
  this.group.add(this.shaft, this.head);
  this.up = new T.Vector3(0, 1, 0);
}

// From `origin` along the unit vector `dir`, `len` long, shaft radius r.
Arrow.prototype.set = function (origin, dir, len, r) {
  var h = Math.min(0.4 * len, 7 * r);
  this.group.position.copy(origin);
  this.group.quaternion.setFromUnitVectors(this.up, dir);
  this.shaft.scale.set(r, len - h, r);
  this.shaft.position.set(0, (len - h) / 2, 0);
  this.head.scale.set(2.6 * r, h, 2.6 * r);
  this.head.position.set(0, len - h / 2, 0);
};

Replay.Markers = function (T, data, scale) {
  this.T = T;
  this.data = data;
  this.group = new T.Group();
  this.pool = [];
  this.dot = new T.SphereGeometry(1, 12, 8);
  this.shaft = new T.CylinderGeometry(1, 1, 1, 10);
  this.head = new T.ConeGeometry(1, 1, 14);
  this.size = scale;
  this._a = new T.Vector3();
  this._b = new T.Vector3();
  this._q = new T.Quaternion();
  var g = data.geometry;
  // Compliance centre and robot frame (held pegs).
  if (data.robot) {
    this.centre = new T.Mesh(this.dot, overlay(T, 0xd81b60));
    this.centre.renderOrder = 11;
    this.centre.scale.setScalar(0.9 * scale);
    this.robot = new T.AxesHelper(1);
    this.robot.material.depthTest = false;
    this.robot.renderOrder = 11;
    this.robot.scale.setScalar(0.5 * g.hole_radius);
    this.group.add(this.centre, this.robot);
  }
  this.trail = new T.Line(new T.BufferGeometry(), new T.LineBasicMaterial({ color: 0x37474f }));
  this.group.add(this.trail);
  // The reference arrow of the force legend, beside the block.
  this.reference = this.arrow(0x555555);
};

// The tip's path over every frame, mapped by f.
Replay.Markers.prototype.setTrail = function (f, visible) {
  var T = this.T, d = this.data, g = d.geometry, n = d.t.length;
  var out = new Float32Array(3 * n), a = this._a, q = this._q;
  for (var i = 0; i < n; i++) {
    q.fromArray(d.orientation, 4 * i);
    a.set(0, 0, -g.centre_height).applyQuaternion(q);
    out[3 * i] = d.centre[3 * i] + a.x;
    out[3 * i + 1] = d.centre[3 * i + 1] + a.y;
    out[3 * i + 2] = d.centre[3 * i + 2] + a.z;
  }
  Replay.mapArray(out, f);
  this.trail.geometry.dispose();
  this.trail.geometry = new T.BufferGeometry();
  this.trail.geometry.setAttribute("position", new T.BufferAttribute(out, 3));
  this.trail.visible = visible;
};

function mapped(v, f) {
  var rho = Math.hypot(v.x, v.y);
  if (rho > 0) {
    var s = f(rho) / rho;
    v.x *= s;
    v.y *= s;
  }
  return v;
}

// Shows frame i: `perNewton` metres of arrow per newton.
Replay.Markers.prototype.show = function (i, f, perNewton) {
  var T = this.T, d = this.data, g = d.geometry, c = d.contacts[i];
  var n = c.length / 11;
  while (this.pool.length < n) {
    var item = {
      dot: new T.Mesh(this.dot, overlay(T, 0x000000)),
      normal: this.arrow(0x000000),
      friction: this.arrow(Replay.FRICTION_COLOR),
    };
    item.dot.renderOrder = 12;
    this.group.add(item.dot);
    this.pool.push(item);
  }
  var a = this._a, b = this._b;
  for (var k = 0; k < this.pool.length; k++) {
    var it = this.pool[k], on = k < n;
    it.dot.visible = it.normal.group.visible = it.friction.group.visible = on;
    if (!on) continue;
    var o = 11 * k, color = Replay.PAIR_COLORS[c[o] % Replay.PAIR_COLORS.length];
    var p = mapped(a.set(c[o + 1], c[o + 2], c[o + 3]), f);
    it.dot.position.copy(p);
    it.dot.scale.setScalar(1.2 * this.size);
    it.dot.material.color.setHex(color);
    // The normal force pushes on the peg: its arrow ends at the point.
    var len = c[o + 7] * perNewton;
    b.set(c[o + 4], c[o + 5], c[o + 6]);
    this.place(it.normal, p, b, len, true);
    it.normal.material.color.setHex(color);
    // Friction acts along the surface from the point.
    b.set(c[o + 8], c[o + 9], c[o + 10]);
    var fl = b.length() * perNewton;
    if (fl > 0) b.normalize();
    this.place(it.friction, p, b, fl, false);
  }
  if (d.robot) {
    var q = this._q;
    q.fromArray(d.orientation, 4 * i);
    a.set(0, 0, g.compliance_height - g.centre_height).applyQuaternion(q);
    a.x += d.centre[3 * i]; a.y += d.centre[3 * i + 1]; a.z += d.centre[3 * i + 2];
    this.centre.position.copy(mapped(a, f));
    var r = d.robot;
    this.robot.position.copy(mapped(b.set(r.position[3 * i], r.position[3 * i + 1], r.position[3 * i + 2]), f));
    this.robot.quaternion.fromArray(r.orientation, 4 * i);
  }
};

Replay.Markers.prototype.arrow = function (color) {
  var a = new Arrow(this.T, color, this.shaft, this.head);
  this.group.add(a.group);
  return a;
};

Replay.Markers.prototype.place = function (arrow, p, dir, len, ending) {
  if (!(len > 0)) {
    arrow.group.visible = false;
    return;
  }
  arrow.group.visible = true;
  var r = Math.min(0.3 * this.size, 0.04 * len);
  var origin = ending ? p.clone().addScaledVector(dir, -len) : p;
  arrow.set(origin, dir, len, Math.max(r, 0.08 * this.size));
};

// The legend's arrow: `force` newtons long at `perNewton`, laid along +x
// at point p.
Replay.Markers.prototype.setReference = function (p, force, perNewton) {
  this.place(this.reference, p, new this.T.Vector3(1, 0, 0), force * perNewton, false);
};
