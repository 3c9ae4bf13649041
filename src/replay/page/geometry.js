// Shapes of the peg and the hole, and the radial exaggeration of the gap.
// Lengths in metres, hole frame: z up along the hole's axis, the top face at
// z = 0, the bore below.
"use strict";

var Replay = window.Replay || (window.Replay = {});

// The radial exaggeration: a map of the distance rho from the hole's axis,
// applied to every drawn point (peg, hole, contacts, arrows' feet, paths).
//
//   f(rho) = rho                      for rho >= R         (outside: true)
//   f(rho) = R - k (R - rho)          for R - w <= rho < R (the band at the wall)
//   f(rho) = rho (R - k w) / (R - w)  for rho < R - w      (inside, compressed)
//
// with R the bore radius and w = 2 c (c the radial clearance): the band holds
// the gap on both sides of a peg off the axis by up to c. f is continuous and
// increasing, so it maps the true scene one-to-one: a gap of g at the wall is
// drawn k g wide, and a contact point that lies on both surfaces stays on
// both. Bodies that cross the band's inner edge look bent there; k = 1 is the
// true scene.
Replay.radialMap = function (R, c, k) {
  var w = 2 * c;
  if (!(k > 1) || !(w > 0) || k * w >= R) {
    return function (rho) { return rho; };
  }
  var inner = (R - k * w) / (R - w);
  return function (rho) {
    if (rho >= R) return rho;
    if (rho >= R - w) return R - k * (R - rho);
    return rho * inner;
  };
};

// The largest exaggeration the map allows (the inside keeps a fifth of R).
Replay.maxExaggeration = function (R, c) {
  return c > 0 ? Math.max(1, Math.floor((0.8 * R) / (2 * c))) : 1;
};

// Maps (x, y) of the flat array `out` (xyz triples) in place.
Replay.mapArray = function (out, f) {
  for (var i = 0; i < out.length; i += 3) {
    var x = out[i], y = out[i + 1];
    var rho = Math.sqrt(x * x + y * y);
    if (rho > 0) {
      var s = f(rho) / rho;
      out[i] = x * s;
      out[i + 1] = y * s;
    }
  }
  return out;
};

// A quarter arc from angle a0 to a1 (radians) about (cx, cy), n points
// after the first.
function arc(points, cx, cy, radius, a0, a1, n) {
  for (var i = 1; i <= n; i++) {
    var a = a0 + ((a1 - a0) * i) / n;
    points.push([cx + radius * Math.cos(a), cy + radius * Math.sin(a)]);
  }
}

// The peg's half profile (radius, height above the tip), tip centre to top
// centre: the flat bottom, the rim fillet, the side, the top face.
Replay.pegProfile = function (g) {
  var r = g.peg_radius, rp = Math.min(g.rim_fillet, 0.999 * r), L = g.peg_length;
  var p = [[0, 0], [r - rp, 0]];
  arc(p, r - rp, rp, rp, -Math.PI / 2, 0, 12);
  p.push([r, L], [0, L]);
  return p;
};

// The block's half profile (radius, z), a closed polygon of solid material:
// the bore's bottom, the wall, the mouth round, the top face, the outside.
// Without a bottom (a planar model) the wall runs to the block's bottom.
Replay.holeProfile = function (g) {
  var R = g.hole_radius, rh = g.mouth_fillet, hb = g.bore_depth;
  var outer = R + Math.max(0.6 * R, 6 * rh);
  var base = hb + Math.max(0.15 * R, 0.1 * hb);
  var p = [];
  if (g.bottom !== false) p.push([0, -hb]);
  p.push([R, g.bottom !== false ? -hb : -base]);
  p.push([R, -rh]);
  arc(p, R + rh, -rh, rh, Math.PI, Math.PI / 2, 16);
  p.push([outer, 0], [outer, -base]);
  if (g.bottom !== false) p.push([0, -base]);
  return { points: p, outer: outer, base: base };
};

// A surface of revolution about z of the profile `pts` (radius, z) over the
// azimuths phi0..phi1: flat arrays of (rho, phi, z) per vertex, and the
// triangle indices. Positions come from `place`.
Replay.revolve = function (pts, phi0, phi1, segments) {
  var cyl = [], index = [];
  var m = pts.length;
  for (var i = 0; i <= segments; i++) {
    var phi = phi0 + ((phi1 - phi0) * i) / segments;
    for (var j = 0; j < m; j++) cyl.push(pts[j][0], phi, pts[j][1]);
  }
  for (var s = 0; s < segments; s++) {
    for (var k = 0; k < m - 1; k++) {
      var a = s * m + k, b = (s + 1) * m + k;
      index.push(a, b, a + 1, a + 1, b, b + 1);
    }
  }
  return { cyl: cyl, index: index };
};

// Cartesian positions of cylindrical (rho, phi, z) triples, rho mapped by f.
Replay.place = function (cyl, f, out) {
  out = out || new Float32Array(cyl.length);
  for (var i = 0; i < cyl.length; i += 3) {
    var rho = f ? f(cyl[i]) : cyl[i];
    out[i] = rho * Math.cos(cyl[i + 1]);
    out[i + 1] = rho * Math.sin(cyl[i + 1]);
    out[i + 2] = cyl[i + 2];
  }
  return out;
};

// The peg's section through its axis (u across, h above the tip), a closed
// polygon: both sides with their rim fillets.
Replay.pegSection = function (g) {
  var half = Replay.pegProfile(g);
  var right = half.slice(1, half.length - 1);
  var left = right.map(function (p) { return [-p[0], p[1]]; }).reverse();
  return right.concat(left);
};
