// The replay page: reads the run (the JSON in #replay-data), builds the
// view, the controls, the timeline with its events and the plots, and keeps
// them on one cursor. Its state is readable as window.pegdynReplay.
"use strict";

(function () {
  var Replay = window.Replay;
  var errors = [];
  window.addEventListener("error", function (e) {
    errors.push(String(e.message || e));
    var b = document.getElementById("error");
    b.hidden = false;
    b.textContent = "Error: " + errors.join("; ");
  });

  var data = JSON.parse(document.getElementById("replay-data").textContent);
  var $ = function (id) { return document.getElementById(id); };
  var t = data.t, n = t.length, t0 = t[0], t1 = t[n - 1] > t0 ? t[n - 1] : t0 + 1e-9;
  var g = data.geometry;

  $("title").textContent = data.title;
  $("subtitle").textContent = data.subtitle;
  if (data.note) {
    $("note").hidden = false;
    $("note").textContent = data.note;
  }
  document.title = data.title + " · pegdyn replay";

  // The view, where the browser can draw it.
  var T = window.PegdynThree, view = null, reason = "";
  if (!T) reason = "the page's renderer did not load";
  else if (!Replay.hasWebGL()) reason = "this browser provides no WebGL";
  if (!reason) {
    try {
      Replay.Orbit = T.OrbitControls;
      view = new Replay.View(T, $("view"), data);
    } catch (e) {
      reason = "WebGL could not start (" + (e && e.message ? e.message : e) + ")";
      view = null;
    }
  }
  if (!view) {
    $("nogl").hidden = false;
    $("nogl").textContent = "The 3-D view needs WebGL: " + reason + ". The timeline, " +
      "the events and the plots below still work; open this file in a browser with WebGL " +
      "(any current Firefox, Chrome, Edge or Safari) to see the peg and the hole.";
  }

  // Plots.
  var plots = [];
  Array.prototype.forEach.call(document.querySelectorAll("#plots canvas"), function (c) {
    var panel = c.getAttribute("data-panel");
    if (data.series.some(function (s) { return s.panel === panel; })) {
      plots.push(new Replay.Plot(c, data, panel, seek));
    } else {
      c.hidden = true;
    }
  });

  // Cursor.
  var state = { time: t0, frame: 0, playing: false, speed: 1 };
  var rate = (t1 - t0) / 12; // simulated seconds per second at speed 1

  function frameAt(time) {
    var lo = 0, hi = n - 1;
    if (time <= t[0]) return 0;
    while (lo < hi) {
      var mid = (lo + hi + 1) >> 1;
      if (t[mid] <= time) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  }

  function seek(time) {
    state.time = Math.min(t1, Math.max(t0, time));
    setFrame(frameAt(state.time));
  }

  function jump(k) {
    var m = data.marks[k];
    if (!m) return;
    state.time = m.t;
    setFrame(m.frame);
    var items = document.querySelectorAll("#events button");
    if (items[k]) items[k].scrollIntoView({ block: "nearest" });
  }

  var series = data.series;
  function setFrame(i) {
    state.frame = i;
    if (view) view.show(i);
    plots.forEach(function (p) { p.setCursor(state.time); });
    $("scrubber").value = String(state.time);
    $("clock").textContent = "t = " + state.time.toFixed(6) + " s  (frame " + (i + 1) + " of " + n + ")";
    var rows = [["contact state", data.states[data.state[i]]]];
    series.forEach(function (s) {
      rows.push([s.name, (+s.values[i].toPrecision(4)) + " " + s.unit]);
    });
    $("readout").innerHTML = "";
    rows.forEach(function (r) {
      var dt = document.createElement("dt"), dd = document.createElement("dd");
      dt.textContent = r[0];
      dd.textContent = r[1];
      $("readout").append(dt, dd);
    });
    var current = -1;
    data.marks.forEach(function (m, k) { if (m.frame <= i) current = k; });
    Array.prototype.forEach.call(document.querySelectorAll("#events button"), function (b, k) {
      b.classList.toggle("current", k === current);
    });
  }

  // Timeline: scrubber, event markers, the event list.
  var scrub = $("scrubber");
  scrub.min = String(t0);
  scrub.max = String(t1);
  scrub.step = "any";
  scrub.addEventListener("input", function () { pause(); seek(parseFloat(scrub.value)); });
  data.marks.forEach(function (m, k) {
    var b = document.createElement("button");
    b.className = "marker " + m.kind;
    b.style.left = (100 * (m.t - t0)) / (t1 - t0) + "%";
    b.title = "t = " + m.t + " s: " + m.label;
    b.setAttribute("data-index", String(k));
    b.addEventListener("click", function () { pause(); jump(k); });
    $("markers").appendChild(b);
    var li = document.createElement("li"), e = document.createElement("button");
    e.className = m.kind;
    e.setAttribute("data-index", String(k));
    e.textContent = m.t.toPrecision(6) + " s  " + m.label;
    e.addEventListener("click", function () { pause(); jump(k); });
    li.appendChild(e);
    $("events").appendChild(li);
  });

  // Play, pause, speed.
  var last = null;
  function tick(now) {
    if (!state.playing) return;
    if (last !== null) {
      var next = state.time + ((now - last) / 1000) * rate * state.speed;
      if (next >= t1) {
        seek(t1);
        pause();
        return;
      }
      seek(next);
    }
    last = now;
    requestAnimationFrame(tick);
  }
  function play() {
    if (state.time >= t1) seek(t0);
    state.playing = true;
    last = null;
    $("play").textContent = "❚❚ Pause";
    requestAnimationFrame(tick);
  }
  function pause() {
    state.playing = false;
    $("play").textContent = "▶ Play";
  }
  $("play").addEventListener("click", function () { if (state.playing) pause(); else play(); });
  [0.05, 0.1, 0.25, 0.5, 1, 2, 4].forEach(function (s) {
    var o = document.createElement("option");
    o.value = String(s);
    o.textContent = "×" + s + "  (" + (+(rate * s).toPrecision(2)) + "× real time)";
    if (s === 1) o.selected = true;
    $("speed").appendChild(o);
  });
  $("speed").addEventListener("change", function () { state.speed = parseFloat($("speed").value); });

  // Display settings.
  var kmax = Replay.maxExaggeration(g.hole_radius, g.hole_radius - g.peg_radius);
  var k0 = Math.min(kmax, Math.max(1, data.exaggeration));
  var ex = $("exaggeration");
  ex.min = "0";
  ex.max = "1";
  ex.step = "0.01";
  ex.value = String(kmax > 1 ? Math.log(k0) / Math.log(kmax) : 0);
  function exaggeration() {
    var v = parseFloat(ex.value);
    return kmax > 1 ? Math.max(1, Math.round(Math.pow(kmax, v))) : 1;
  }
  function settings() {
    if (!view) return;
    view.settings.exaggeration = exaggeration();
    view.settings.cut = (parseFloat($("cut").value) * Math.PI) / 180;
    view.settings.glass = $("glass").checked;
    view.settings.trail = $("trail").checked;
    view.settings.arrows = Math.pow(10, parseFloat($("arrows").value));
    $("k-text").textContent = String(view.settings.exaggeration);
    $("gap-text").textContent = (1e6 * (g.hole_radius - g.peg_radius)).toPrecision(3) +
      " µm drawn as " + (1e6 * (g.hole_radius - g.peg_radius) * view.settings.exaggeration).toPrecision(3) + " µm";
    view.apply();
  }
  ["exaggeration", "cut", "glass", "trail", "arrows"].forEach(function (id) {
    $(id).addEventListener("input", settings);
  });
  if (data.view === "section") $("cut-row").hidden = true;
  $("home").addEventListener("click", function () { if (view) view.home(); });
  $("close").addEventListener("click", function () { if (view) view.closeUp(); });

  // Legend.
  var used = {};
  data.contacts.forEach(function (c) { for (var k = 0; k < c.length; k += 11) used[c[k]] = true; });
  var items = data.pairs.map(function (name, k) {
    if (!used[k]) return null;
    var hex = Replay.PAIR_COLORS[k % Replay.PAIR_COLORS.length].toString(16);
    return ["#" + "000000".slice(hex.length) + hex, name + ": point and normal force"];
  }).filter(Boolean);
  items.push(["#222222", "friction force"]);
  if (data.robot) {
    items.push(["#d81b60", "compliance centre"]);
    items.push(["linear-gradient(90deg,#f00,#0f0,#00f)", "robot frame (x, y, z)"]);
  }
  items.push(["#37474f", "path of the tip"]);
  items.forEach(function (it) {
    var row = document.createElement("div"), sw = document.createElement("span");
    sw.className = "swatch";
    sw.style.background = it[0];
    row.append(sw, document.createTextNode(it[1]));
    $("legend").appendChild(row);
  });

  // The force scale's label follows the reference arrow on the screen.
  if (view) {
    view.onRender = function () {
      var a = view.markers.reference.group;
      if (!a.visible) return;
      var f = view.referenceForce(), end = a.position.clone();
      var s = view.project(end);
      var r = $("view").getBoundingClientRect();
      var label = $("force-label");
      label.textContent = "→ " + (+f.toPrecision(3)) + " N";
      label.style.left = s.x - r.left + "px";
      label.style.top = s.y - r.top + 6 + "px";
    };
  }

  // Keys: space plays or pauses, arrows step a frame, [ and ] jump events.
  window.addEventListener("keydown", function (e) {
    if (e.target && (e.target.tagName === "INPUT" || e.target.tagName === "SELECT")) return;
    if (e.key === " ") { e.preventDefault(); if (state.playing) pause(); else play(); }
    else if (e.key === "ArrowRight") { pause(); state.time = t[Math.min(n - 1, state.frame + 1)]; setFrame(frameAt(state.time)); }
    else if (e.key === "ArrowLeft") { pause(); state.time = t[Math.max(0, state.frame - 1)]; setFrame(frameAt(state.time)); }
    else if (e.key === "]" || e.key === "[") {
      pause();
      var k = -1;
      data.marks.forEach(function (m, j) {
        if (e.key === "]" && k < 0 && m.t > state.time) k = j;
        if (e.key === "[" && m.t < state.time) k = j;
      });
      if (k >= 0) jump(k);
    }
  });
  window.addEventListener("resize", function () { plots.forEach(function (p) { p.draw(); }); });

  settings();
  var hash = /^#(t|event)=([^&]+)$/.exec(location.hash || "");
  if (hash && hash[1] === "t") seek(parseFloat(hash[2]));
  else if (hash) jump(parseInt(hash[2], 10));
  else seek(t0);

  window.pegdynReplay = {
    ready: true,
    webgl: !!view,
    frames: n,
    marks: data.marks,
    errors: errors,
    get time() { return state.time; },
    get frame() { return state.frame; },
    get playing() { return state.playing; },
    get renders() { return view ? view.renders : 0; },
    get scrubber() { return parseFloat(scrub.value); },
    get cursor() { return plots.length ? plots[0].cursor : state.time; },
    seek: seek,
    jump: jump,
    step: function (i) {
      var k = Math.max(0, Math.min(n - 1, i));
      state.time = t[k];
      setFrame(k);
    },
    play: play,
    pause: pause,
    pegBox: function () { return view ? view.pegBox() : null; },
    render: function () { if (view) view.render(); },
  };
})();
