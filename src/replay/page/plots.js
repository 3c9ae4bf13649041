// The plots under the view: one canvas per panel (forces, depth, tilt),
// every series against time, the events as ticks, a cursor at the time
// shown. A click or a drag on a plot moves the cursor there.
"use strict";

var Replay = window.Replay || (window.Replay = {});

Replay.SERIES_COLORS = ["#1565c0", "#e65100", "#2e7d32", "#6a1b9a", "#c62828", "#00838f"];
Replay.MARK_COLORS = { contact: "#78909c", seat: "#2e7d32", limit: "#c62828", stop: "#6d4c41", end: "#263238" };

Replay.PANEL_TITLES = { force: "Forces", depth: "Tip depth", tilt: "Tilt" };

Replay.Plot = function (canvas, data, panel, seek) {
  this.canvas = canvas;
  this.data = data;
  this.series = data.series.filter(function (s) { return s.panel === panel; });
  this.panel = panel;
  this.t = data.t;
  var lo = Infinity, hi = -Infinity;
  this.series.forEach(function (s) {
    s.values.forEach(function (v) {
      lo = Math.min(lo, v);
      hi = Math.max(hi, v);
    });
  });
  if (!(hi > lo)) {
    lo = (isFinite(lo) ? lo : 0) - 1;
    hi = lo + 2;
  }
  var pad = 0.06 * (hi - lo);
  this.lo = lo - pad;
  this.hi = hi + pad;
  this.cursor = 0;
  var self = this, dragging = false;
  function at(ev) {
    var r = canvas.getBoundingClientRect();
    var x = (ev.clientX - r.left - self.left) / (r.width - self.left - self.right);
    seek(self.t0() + Math.min(1, Math.max(0, x)) * (self.t1() - self.t0()));
  }
  canvas.addEventListener("pointerdown", function (ev) { dragging = true; at(ev); });
  canvas.addEventListener("pointermove", function (ev) { if (dragging) at(ev); });
  window.addEventListener("pointerup", function () { dragging = false; });
};

Replay.Plot.prototype.t0 = function () { return this.t[0]; };
Replay.Plot.prototype.t1 = function () {
  var t = this.t;
  return t[t.length - 1] > t[0] ? t[t.length - 1] : t[0] + 1;
};

function tickText(v) {
  var a = Math.abs(v);
  if (a === 0) return "0";
  if (a >= 1e4 || a < 1e-2) return v.toExponential(1);
  return (+v.toPrecision(3)).toString();
}

Replay.Plot.prototype.draw = function () {
  var c = this.canvas, dpr = window.devicePixelRatio || 1;
  var w = c.clientWidth, h = c.clientHeight;
  if (c.width !== Math.round(w * dpr) || c.height !== Math.round(h * dpr)) {
    c.width = Math.round(w * dpr);
    c.height = Math.round(h * dpr);
  }
  var ctx = c.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  this.left = 46;
  this.right = 8;
  var top = 18, bottom = 16, L = this.left, W = w - L - this.right, H = h - top - bottom;
  var t0 = this.t0(), t1 = this.t1(), lo = this.lo, hi = this.hi;
  var X = function (t) { return L + ((t - t0) / (t1 - t0)) * W; };
  var Y = function (v) { return top + (1 - (v - lo) / (hi - lo)) * H; };
  ctx.font = "11px system-ui, sans-serif";
  ctx.fillStyle = "#263238";
  var unit = this.series.length ? this.series[0].unit : "";
  ctx.fillText((Replay.PANEL_TITLES[this.panel] || this.panel) + (unit ? " [" + unit + "]" : ""), L, 12);
  ctx.strokeStyle = "#cfd8dc";
  ctx.strokeRect(L, top, W, H);
  ctx.fillStyle = "#546e7a";
  ctx.textAlign = "right";
  ctx.fillText(tickText(hi), L - 4, top + 9);
  ctx.fillText(tickText(lo), L - 4, top + H);
  ctx.textAlign = "left";
  ctx.fillText(tickText(t0) + " s", L, h - 3);
  ctx.textAlign = "right";
  ctx.fillText(tickText(t1) + " s", L + W, h - 3);
  ctx.textAlign = "left";
  // Events: ticks along the top edge.
  this.data.marks.forEach(function (m) {
    ctx.strokeStyle = Replay.MARK_COLORS[m.kind] || "#78909c";
    ctx.beginPath();
    ctx.moveTo(X(m.t), top);
    ctx.lineTo(X(m.t), top + 6);
    ctx.stroke();
  });
  var t = this.t, legend = top + 12;
  this.series.forEach(function (s, k) {
    ctx.strokeStyle = Replay.SERIES_COLORS[k % Replay.SERIES_COLORS.length];
    ctx.lineWidth = 1.3;
    ctx.beginPath();
    for (var i = 0; i < t.length; i++) {
      if (i === 0) ctx.moveTo(X(t[i]), Y(s.values[i]));
      else ctx.lineTo(X(t[i]), Y(s.values[i]));
    }
    ctx.stroke();
    ctx.fillStyle = ctx.strokeStyle;
    ctx.textAlign = "right";
    ctx.fillText(s.name, L + W - 4, legend);
    ctx.textAlign = "left";
    legend += 13;
  });
  ctx.lineWidth = 1;
  ctx.strokeStyle = "#d32f2f";
  ctx.beginPath();
  ctx.moveTo(X(this.cursor), top);
  ctx.lineTo(X(this.cursor), top + H);
  ctx.stroke();
};

Replay.Plot.prototype.setCursor = function (t) {
  this.cursor = t;
  this.draw();
};
