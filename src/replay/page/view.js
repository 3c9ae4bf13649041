// The 3-D view: renderer, camera and orbit controls, the bodies and the
// markers; draws one frame on demand.
"use strict";

var Replay = window.Replay || (window.Replay = {});

// Whether this browser can make a WebGL context (without keeping it).
Replay.hasWebGL = function () {
  try {
    var c = document.createElement("canvas");
    return !!(window.WebGLRenderingContext && (c.getContext("webgl2") || c.getContext("webgl")));
  } catch (e) {
    return false;
  }
};

Replay.View = function (T, container, data) {
  var g = data.geometry, section = data.view === "section";
  this.T = T;
  this.data = data;
  this.section = section;
  this.container = container;
  this.renderer = new T.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  this.renderer.setClearColor(0xf4f6f8, 1);
  container.appendChild(this.renderer.domElement);
  this.scene = new T.Scene();
  var size = Math.max(g.hole_radius * 3, g.peg_length);
  this.size = size;
  this.camera = new T.PerspectiveCamera(35, 1, size / 20000, size * 200);
  this.camera.up.set(0, 0, 1);
  this.controls = new Replay.Orbit(this.camera, this.renderer.domElement);
  this.controls.minDistance = size / 5000;
  this.controls.maxDistance = size * 40;
  this.controls.screenSpacePanning = true;
  if (section) this.controls.enableRotate = false;
  this.scene.add(new T.HemisphereLight(0xffffff, 0x8090a0, 2.2));
  this.light = new T.DirectionalLight(0xffffff, 2.2);
  this.camera.add(this.light);
  this.light.position.set(0.3, 0.6, 0.2);
  var fill = new T.DirectionalLight(0xffffff, 1.1);
  fill.position.set(-0.7, 0.1, 0.3);
  this.camera.add(fill);
  this.scene.add(this.camera);
  this.block = new Replay.Block(T, g, section);
  this.peg = new Replay.Peg(T, g, section);
  this.markers = new Replay.Markers(T, data, g.peg_length / 160);
  this.scene.add(this.block.group, this.peg.mesh, this.markers.group);
  this.settings = {
    exaggeration: data.exaggeration,
    cut: section ? 0 : Math.PI / 2,
    glass: false,
    trail: true,
    arrows: 1,
  };
  // Arrows: the largest normal force of the run is 30 % of the peg long.
  var fmax = 0;
  data.contacts.forEach(function (c) {
    for (var k = 7; k < c.length; k += 11) fmax = Math.max(fmax, c[k]);
  });
  this.fmax = fmax > 0 ? fmax : 1;
  this.basePerNewton = (0.3 * g.peg_length) / this.fmax;
  this.frame = 0;
  this.renders = 0;
  this._p = new T.Vector3();
  this._q = new T.Quaternion();
  this.home();
  var self = this;
  this.controls.addEventListener("change", function () { self.request(); });
  this.resize();
  window.addEventListener("resize", function () { self.resize(); });
  this.apply();
};

// The camera back to its first pose.
Replay.View.prototype.home = function () {
  var g = this.data.geometry, s = this.size, target;
  if (this.section) {
    target = new this.T.Vector3(0, 0, 0.1 * g.peg_length);
    this.camera.position.set(0, -2.6 * s, target.z);
  } else {
    target = new this.T.Vector3(0, 0, 0.25 * g.peg_length);
    this.camera.position.set(1.7 * s, -2.4 * s, target.z + 1.3 * s);
  }
  this.controls.target.copy(target);
  this.camera.lookAt(target);
  this.controls.update();
  this.request();
};

// Closer to the mouth, where the contacts are.
Replay.View.prototype.closeUp = function () {
  var g = this.data.geometry, s = 0.35 * this.size;
  var target = new this.T.Vector3(this.section ? 0 : 0, 0, -0.05 * g.peg_length);
  if (this.section) this.camera.position.set(0, -2.6 * s, target.z);
  else this.camera.position.set(1.35 * s, -1.9 * s, target.z + 1.1 * s);
  this.controls.target.copy(target);
  this.controls.update();
  this.request();
};

Replay.View.prototype.map = function () {
  var g = this.data.geometry;
  return Replay.radialMap(g.hole_radius, g.hole_radius - g.peg_radius, this.settings.exaggeration);
};

// Rebuilds what depends on the settings, then redraws.
Replay.View.prototype.apply = function () {
  var f = this.map(), s = this.settings;
  this.block.build(f, s.cut, s.glass);
  this.markers.setTrail(f, s.trail);
  this.show(this.frame);
};

Replay.View.prototype.perNewton = function () {
  return this.basePerNewton * this.settings.arrows;
};

// A round force of about a fifth of the peg's length at the current scale,
// for the legend.
Replay.View.prototype.referenceForce = function () {
  var f = (0.2 * this.data.geometry.peg_length) / this.perNewton();
  var p = Math.pow(10, Math.floor(Math.log10(f)));
  var m = f / p;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
};

Replay.View.prototype.show = function (i) {
  var d = this.data, f = this.map();
  this.frame = i;
  var p = this._p.fromArray(d.centre, 3 * i), q = this._q.fromArray(d.orientation, 4 * i);
  this.peg.place(p, q, f);
  this.markers.show(i, f, this.perNewton());
  var g = d.geometry, outer = this.block.profile.outer;
  this.markers.setReference(
    new this.T.Vector3(-outer, this.section ? 0 : -1.2 * outer, this.section ? 0.05 * g.peg_length : 0),
    this.referenceForce(), this.perNewton());
  this.request();
};

Replay.View.prototype.resize = function () {
  var w = this.container.clientWidth || 300, h = this.container.clientHeight || 200;
  this.renderer.setSize(w, h, false);
  this.renderer.domElement.style.width = "100%";
  this.renderer.domElement.style.height = "100%";
  this.camera.aspect = w / h;
  this.camera.updateProjectionMatrix();
  this.request();
};

Replay.View.prototype.request = function () {
  if (this.pending) return;
  this.pending = true;
  var self = this;
  requestAnimationFrame(function () {
    self.pending = false;
    self.render();
  });
};

// Draws now: the cut-away wedge turned towards the camera first.
Replay.View.prototype.render = function () {
  var c = this.camera.position, t = this.controls.target;
  if (!this.section) this.block.group.rotation.z = Math.atan2(c.y - t.y, c.x - t.x);
  this.renderer.render(this.scene, this.camera);
  this.renders += 1;
  if (this.onRender) this.onRender();
};

// Where a world point falls on the page (CSS pixels).
Replay.View.prototype.project = function (v) {
  var r = this.renderer.domElement.getBoundingClientRect();
  var p = v.clone().project(this.camera);
  return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
};

// The peg's bounding box on the page (CSS pixels) at the frame shown.
Replay.View.prototype.pegBox = function () {
  var b = this.peg.geo.boundingBox, T = this.T;
  var xs = [], ys = [];
  for (var k = 0; k < 8; k++) {
    var v = new T.Vector3(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z);
    var s = this.project(v);
    xs.push(s.x);
    ys.push(s.y);
  }
  return {
    left: Math.min.apply(null, xs), top: Math.min.apply(null, ys),
    right: Math.max.apply(null, xs), bottom: Math.max.apply(null, ys),
  };
};
