// polysect live page: draws what the server's simulation sends and forwards edits.
// All geometry decisions are made in Rust; this file keeps the picture and the controls.
"use strict";
(() => {
  const $ = (id) => document.getElementById(id);
  const canvas = $("view");
  const ctx = canvas.getContext("2d");
  const params = new URLSearchParams(location.search);
  // ?unthrottled: draw and ask for the next frame as soon as one arrives (measures the
  // whole pipeline's capacity instead of following the display's refresh).
  const unthrottled = params.has("unthrottled");
  const FILL = "#a9c4e8", STROKE = "#2d5a96", HIT_FILL = "rgba(235,86,54,0.55)", HIT_STROKE = "#b3260d";
  const littleEndian = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;

  const S = {
    ws: null, ready: false, scene: 0, world: [1200, 800], sizes: null,
    // Per polygon: ids, c (shape coordinates x0, y0, x1, y1, ...), box (of c), path and
    // handles (cached, in pixels of shape coordinates); w (the world points of the last
    // frame, when the server sends them), wbox, wpath, whandles (rebuilt per frame).
    polys: [],
    poses: new Float64Array(0), // c, s, tx, ty per polygon
    awaiting: null, // a frame whose world points are the next binary message
    pairs: [], normals: [], hit: new Uint8Array(0),
    settings: null, frame: 0, last: null, pending: null, inflight: false, dirty: true,
    edits: 0, editsAtFrame: 0, moveInflight: false, moveQueued: null, drag: null, hover: null,
    times: [], fps: 0, drawMs: 0, refusals: 0, errors: 0, lastRefusal: "", lastError: "",
    view: { scale: 1, ox: 0, oy: 0, dpr: 1 }, figuresAt: 0, figuresOf: null, appliedParams: false,
    trace: null, traceStep: 0, traces: 0,
    // The trace paused a running simulation: Close (or a new scene) resumes it.
    resumeAfterTrace: false, statusKind: "", numbered: 0, traceZoom: 0,
  };

  function send(msg) {
    if (S.ws && S.ws.readyState === WebSocket.OPEN) S.ws.send(JSON.stringify(msg));
  }
  function status(text, kind) {
    const el = $("status");
    el.textContent = text;
    el.className = kind || "";
    S.statusKind = kind || "";
  }
  // A success replaces an error or a refusal still on show (it is about an older action).
  function clearStaleError(text) {
    if (S.statusKind === "error" || S.statusKind === "refused") status(text, "ok");
  }
  // Resumes the simulation if a trace paused it.
  function resumeIfTracePaused() {
    if (S.resumeAfterTrace) {
      S.resumeAfterTrace = false;
      // Sent even if the pause is not confirmed yet: it may still be on its way.
      send({ op: "settings", paused: false });
    }
  }

  // ---- connection ----
  function connect() {
    const ws = new WebSocket(`ws://${location.host}/ws`);
    ws.binaryType = "arraybuffer";
    S.ws = ws;
    ws.onopen = () => status("connected", "ok");
    ws.onclose = () => { S.ready = false; status("disconnected: reload the page to start again", "error"); };
    ws.onmessage = (ev) => (typeof ev.data === "string" ? onText(JSON.parse(ev.data)) : onBinary(ev.data));
  }

  function onText(m) {
    switch (m.type) {
      case "settings": onSettings(m); break;
      case "scene":
        S.sizes = m.sizes; S.world = m.world; S.scene = m.scene; S.ready = false; S.trace = null; showTraceStep(); resize();
        resumeIfTracePaused();
        if (S.scene > 1) status(`New scene: ${m.sizes.length} polygons`, "ok");
        break;
      case "frame": if (m.world) S.awaiting = m; else onFrame(m); break;
      case "edit": onEdit(m); break;
      case "trace": onTrace(m); break;
      case "refused":
        S.refusals++; S.lastRefusal = m.reason; S.moveInflight = false;
        status(`Refused ${m.op} on polygon ${m.polygon}: ${m.reason}`, "refused");
        flushMove(); break;
      case "error":
        S.errors++; S.lastError = m.message; S.moveInflight = false;
        status(`Error: ${m.message}`, "error");
        flushMove(); break;
    }
  }

  function floats(buf) {
    if (littleEndian) return new Float64Array(buf);
    const dv = new DataView(buf), all = new Float64Array(buf.byteLength / 8);
    for (let i = 0; i < all.length; i++) all[i] = dv.getFloat64(8 * i, true);
    return all;
  }
  // A binary message is a frame's world points when a frame announced them, else a new
  // scene's shapes.
  function onBinary(buf) {
    const all = floats(buf);
    if (S.awaiting) {
      const m = S.awaiting;
      S.awaiting = null;
      m.worldPoints = all;
      onFrame(m);
      return;
    }
    let at = 0;
    S.polys = S.sizes.map((n) => {
      const c = all.slice(at, at + 2 * n);
      at += 2 * n;
      return { ids: Int32Array.from({ length: n }, (_, k) => k), c, path: null, handles: null, box: bbox(c) };
    });
    S.poses = new Float64Array(4 * S.polys.length);
    for (let i = 0; i < S.polys.length; i++) S.poses[4 * i] = 1;
    S.pairs = []; S.normals = []; S.hit = new Uint8Array(S.polys.length);
    S.frame = 0; S.last = null; S.pending = null; S.inflight = false; S.drag = null; S.hover = null;
    S.ready = true; S.dirty = true;
    S.times = [];
    requestFrame(true);
  }

  function onSettings(m) {
    S.settings = m;
    for (const k of ["polygons", "vertices", "seed", "strategy", "precision", "speed"]) $(k).value = m[k];
    $("speedValue").textContent = Number(m.speed).toFixed(1);
    $("pause").textContent = m.paused ? "Resume" : "Pause";
    clearStaleError(`Settings in force: ${m.paused ? "paused" : "running"}, ${m.strategy}, ${m.precision}`);
    if (!S.appliedParams) {
      // Settings from the address (?polygons=200&vertices=64&strategy=cached ...).
      S.appliedParams = true;
      const change = {};
      for (const k of ["polygons", "vertices", "seed", "speed"]) if (params.has(k)) change[k] = Number(params.get(k));
      for (const k of ["strategy", "precision"]) if (params.has(k)) change[k] = params.get(k);
      if (params.has("paused")) change.paused = params.get("paused") !== "false";
      if (Object.keys(change).length) send({ op: "settings", ...change });
    }
    if (!m.paused) requestFrame();
  }

  function requestFrame(force) {
    if (!S.ready || S.inflight || (!force && S.settings && S.settings.paused)) return;
    S.inflight = true;
    send({ op: "frame" });
  }

  function onFrame(m) {
    S.inflight = false;
    if (m.scene !== S.scene || !S.ready) return;
    m.editsSeen = S.edits;
    S.pending = m;
    if (unthrottled) { applyFrame(); draw(); requestFrame(); }
  }

  function applyFrame() {
    const m = S.pending;
    S.pending = null;
    S.last = m;
    S.frame = m.frame;
    S.editsAtFrame = m.editsSeen;
    S.poses = Float64Array.from(m.poses);
    // World points only when they follow this polygon's shape (an edit since changes
    // the shape; its world points come with the next frame).
    let at = 0;
    for (const p of S.polys) {
      const n = p.ids.length;
      p.w = m.worldPoints && m.editsSeen === S.edits ? m.worldPoints.subarray(at, at + 2 * n) : null;
      p.wbox = p.w && bbox(p.w); p.wpath = null; p.whandles = null;
      at += 2 * n;
    }
    S.pairs = m.pairs; S.normals = m.normals;
    S.hit = new Uint8Array(S.polys.length);
    for (const [i, j] of m.pairs) { S.hit[i] = 1; S.hit[j] = 1; }
    if (m.advanced) {
      const now = performance.now();
      S.times.push(now);
      while (S.times.length > 2 && now - S.times[0] > 1000) S.times.shift();
      S.fps = S.times.length > 1 ? (1000 * (S.times.length - 1)) / (now - S.times[0]) : 0;
    }
    S.dirty = true;
  }

  // ---- edits ----
  function onEdit(m) {
    const p = S.polys[m.polygon];
    if (!p) return;
    const at = (id) => p.ids.indexOf(id);
    if (m.kind === "move") {
      const k = at(m.vertex);
      p.c[2 * k] = m.point[0]; p.c[2 * k + 1] = m.point[1];
      S.moveInflight = false;
    } else if (m.kind === "insert") {
      const k = at(m.after) + 1, n = p.ids.length;
      const ids = new Int32Array(n + 1), c = new Float64Array(2 * n + 2);
      ids.set(p.ids.subarray(0, k)); ids[k] = m.vertex; ids.set(p.ids.subarray(k), k + 1);
      c.set(p.c.subarray(0, 2 * k)); c[2 * k] = m.point[0]; c[2 * k + 1] = m.point[1]; c.set(p.c.subarray(2 * k), 2 * k + 2);
      p.ids = ids; p.c = c;
    } else if (m.kind === "remove") {
      const k = at(m.vertex), n = p.ids.length;
      const ids = new Int32Array(n - 1), c = new Float64Array(2 * n - 2);
      ids.set(p.ids.subarray(0, k)); ids.set(p.ids.subarray(k + 1), k);
      c.set(p.c.subarray(0, 2 * k)); c.set(p.c.subarray(2 * k + 2), 2 * k);
      p.ids = ids; p.c = c;
    }
    p.path = null; p.handles = null; p.box = bbox(p.c); p.w = null;
    S.edits++;
    S.dirty = true;
    if (m.kind !== "move") status(`${m.kind === "insert" ? "Inserted" : "Removed"} vertex ${m.vertex} of polygon ${m.polygon}`, "ok");
    else clearStaleError(`Moved vertex ${m.vertex} of polygon ${m.polygon}`);
    if (S.settings.paused) requestFrame(true); // the pairs for the edited polygon
    flushMove();
  }

  function sendMove(poly, vertex, to) {
    if (S.moveInflight) { S.moveQueued = { poly, vertex, to }; return; }
    S.moveInflight = true;
    send({ op: "move", scene: S.scene, polygon: poly, vertex, to });
  }
  function flushMove() {
    if (!S.moveInflight && S.moveQueued) {
      const q = S.moveQueued;
      S.moveQueued = null;
      sendMove(q.poly, q.vertex, q.to);
    }
  }

  // ---- view and picking ----
  function bbox(c) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let k = 0; k < c.length; k += 2) {
      const x = c[k], y = c[k + 1];
      if (x < x0) x0 = x; if (x > x1) x1 = x; if (y < y0) y0 = y; if (y > y1) y1 = y;
    }
    return [x0, y0, x1, y1];
  }
  function resize() {
    const r = canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1, v = S.view;
    canvas.width = Math.round(r.width * dpr); canvas.height = Math.round(r.height * dpr);
    const pad = 12;
    v.dpr = dpr;
    v.scale = Math.min((r.width - 2 * pad) / S.world[0], (r.height - 2 * pad) / S.world[1]);
    v.ox = (r.width - S.world[0] * v.scale) / 2; v.oy = (r.height - S.world[1] * v.scale) / 2;
    for (const p of S.polys) { p.path = null; p.handles = null; }
    S.dirty = true;
  }
  const toWorld = (mx, my) => [(mx - S.view.ox) / S.view.scale, (my - S.view.oy) / S.view.scale];
  function mouse(ev) {
    const r = canvas.getBoundingClientRect();
    return toWorld(ev.clientX - r.left, ev.clientY - r.top);
  }

  // The pose's map of shape point (x, y) to the world, and its inverse (for drawing and
  // picking only: the server maps edit targets itself).
  function toPose(i, x, y) {
    const q = S.poses, c = q[4 * i], s = q[4 * i + 1];
    return [c * x - s * y + q[4 * i + 2], s * x + c * y + q[4 * i + 3]];
  }
  function fromPose(i, x, y) {
    const q = S.poses, c = q[4 * i], s = q[4 * i + 1], rx = x - q[4 * i + 2], ry = y - q[4 * i + 3], l = c * c + s * s;
    return [(c * rx + s * ry) / l, (c * ry - s * rx) / l];
  }
  // Polygon i's points to pick on (its world points when the page has them, else its
  // shape) and the world point w in the same frame.
  function pickFrame(i, w) {
    const p = S.polys[i];
    return p.w ? { c: p.w, b: p.wbox, at: w } : { c: p.c, b: p.box, at: fromPose(i, w[0], w[1]) };
  }
  // The world position of polygon i's k-th vertex.
  function worldVertex(i, k) {
    const p = S.polys[i];
    return p.w ? [p.w[2 * k], p.w[2 * k + 1]] : toPose(i, p.c[2 * k], p.c[2 * k + 1]);
  }
  // Nearest vertex within `px` pixels, over polygons whose box is near; topmost first.
  function pickVertex(w, px) {
    const tol = px / S.view.scale;
    let best = null, bestD = tol * tol;
    for (let i = S.polys.length - 1; i >= 0; i--) {
      const p = S.polys[i], f = pickFrame(i, w), [x, y] = f.at, b = f.b, c = f.c;
      if (x < b[0] - tol || x > b[2] + tol || y < b[1] - tol || y > b[3] + tol) continue;
      for (let k = 0; k < p.ids.length; k++) {
        const dx = c[2 * k] - x, dy = c[2 * k + 1] - y, d = dx * dx + dy * dy;
        if (d <= bestD) { bestD = d; best = { poly: i, vertex: p.ids[k] }; }
      }
      if (best) return best;
    }
    return null;
  }
  // Nearest edge within `px` pixels: the polygon and the edge's first vertex.
  function pickEdge(w, px) {
    const tol = px / S.view.scale;
    for (let i = S.polys.length - 1; i >= 0; i--) {
      const p = S.polys[i], f = pickFrame(i, w), [x, y] = f.at, b = f.b, c = f.c, n = p.ids.length;
      if (x < b[0] - tol || x > b[2] + tol || y < b[1] - tol || y > b[3] + tol) continue;
      let best = -1, bestD = tol * tol;
      for (let k = 0; k < n; k++) {
        const ax = c[2 * k], ay = c[2 * k + 1], k2 = (k + 1) % n, bx = c[2 * k2], by = c[2 * k2 + 1];
        const ex = bx - ax, ey = by - ay, len = ex * ex + ey * ey;
        const t = len > 0 ? Math.max(0, Math.min(1, ((x - ax) * ex + (y - ay) * ey) / len)) : 0;
        const dx = ax + t * ex - x, dy = ay + t * ey - y, d = dx * dx + dy * dy;
        if (d <= bestD) { bestD = d; best = k; }
      }
      if (best >= 0) return { poly: i, after: p.ids[best] };
    }
    return null;
  }

  canvas.addEventListener("mousedown", (ev) => {
    if (ev.button !== 0 || !S.ready) return;
    const w = mouse(ev), v = pickVertex(w, 8);
    if (v) { S.drag = v; ev.preventDefault(); return; }
    const e = pickEdge(w, 6);
    if (e) send({ op: "insert", scene: S.scene, polygon: e.poly, after: e.after, point: w });
  });
  window.addEventListener("mousemove", (ev) => {
    if (S.drag) { sendMove(S.drag.poly, S.drag.vertex, mouse(ev)); return; }
    if ($("showVertices").checked && S.ready) {
      const h = pickVertex(mouse(ev), 8);
      if ((h && (!S.hover || h.poly !== S.hover.poly || h.vertex !== S.hover.vertex)) || (!h && S.hover)) { S.hover = h; S.dirty = true; }
    }
  });
  window.addEventListener("mouseup", () => { S.drag = null; });
  const removeAt = (ev) => {
    const v = S.ready && pickVertex(mouse(ev), 8);
    if (v) { ev.preventDefault(); send({ op: "remove", scene: S.scene, polygon: v.poly, vertex: v.vertex }); }
  };
  canvas.addEventListener("dblclick", removeAt);
  canvas.addEventListener("contextmenu", removeAt);

  // ---- drawing ----
  // The outline in pixels, decimated to the half-pixel grid: a vertex is kept only if it
  // falls in another half-pixel cell than the last one kept, so a 65,536-vertex polygon
  // becomes a few hundred points. From the world points when the frame brought them
  // (rebuilt per frame: what the store holds, exactly), else from the shape (rebuilt
  // after an edit or a resize, drawn under the pose's transform).
  function pathOf(p) {
    if (p.w ? p.wpath : p.path) return p.w ? p.wpath : p.path;
    const s = S.view.scale, c = p.w || p.c, path = new Path2D();
    let lx = NaN, ly = NaN, kept = 0;
    for (let k = 0; k < c.length; k += 2) {
      const x = c[k] * s, y = c[k + 1] * s, cx = Math.round(2 * x), cy = Math.round(2 * y);
      if (cx === lx && cy === ly) continue;
      if (kept++ === 0) path.moveTo(x, y); else path.lineTo(x, y);
      lx = cx; ly = cy;
    }
    path.closePath();
    if (p.w) p.wpath = path; else p.path = path;
    p.kept = kept;
    return path;
  }
  // Handles only where vertices are at least 5 px apart on average.
  function handlesOf(p) {
    const cached = p.w ? p.whandles : p.handles;
    if (cached !== null && cached !== undefined) return cached;
    const s = S.view.scale, n = p.ids.length, b = p.box, c = p.w || p.c;
    const perimeter = 2 * ((b[2] - b[0]) + (b[3] - b[1])) * s;
    let h = false;
    if (perimeter / n >= 5) {
      h = new Path2D();
      for (let k = 0; k < n; k++) h.rect(c[2 * k] * s - 2, c[2 * k + 1] * s - 2, 4, 4);
    }
    if (p.w) p.whandles = h; else p.handles = h;
    return h;
  }

  function draw() {
    const t0 = performance.now(), v = S.view, d = v.dpr;
    ctx.setTransform(d, 0, 0, d, 0, 0);
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    ctx.fillStyle = "#fbfcfe"; ctx.strokeStyle = "#9aa3b2"; ctx.lineWidth = 1;
    ctx.fillRect(v.ox, v.oy, S.world[0] * v.scale, S.world[1] * v.scale);
    ctx.strokeRect(v.ox, v.oy, S.world[0] * v.scale, S.world[1] * v.scale);
    const handles = $("showVertices").checked;
    for (let i = 0; i < S.polys.length; i++) {
      const p = S.polys[i];
      if (p.w) ctx.setTransform(d, 0, 0, d, d * v.ox, d * v.oy);
      else {
        const q = S.poses, c = q[4 * i], s = q[4 * i + 1];
        ctx.setTransform(d * c, d * s, -d * s, d * c, d * (v.ox + q[4 * i + 2] * v.scale), d * (v.oy + q[4 * i + 3] * v.scale));
      }
      const path = pathOf(p);
      ctx.fillStyle = S.hit[i] ? HIT_FILL : FILL;
      ctx.fill(path);
      ctx.strokeStyle = S.hit[i] ? HIT_STROKE : STROKE;
      ctx.lineWidth = S.hit[i] ? 1.6 : 1;
      ctx.stroke(path);
      const h = handles && handlesOf(p);
      if (h) { ctx.fillStyle = "#1d2330"; ctx.fill(h); }
    }
    ctx.setTransform(d, 0, 0, d, 0, 0);
    if ($("showNumbers").checked) drawNumbers(); else S.numbered = 0;
    if ($("showNormals").checked) {
      ctx.strokeStyle = "#5a0f00"; ctx.lineWidth = 2;
      ctx.beginPath();
      S.pairs.forEach(([i, j], k) => {
        const n = S.normals[k];
        if (!n) return;
        const ci = centre(i), cj = centre(j), mx = (ci[0] + cj[0]) / 2, my = (ci[1] + cj[1]) / 2;
        const sx = v.ox + mx * v.scale, sy = v.oy + my * v.scale;
        ctx.moveTo(sx - 9 * n[0], sy - 9 * n[1]); ctx.lineTo(sx + 9 * n[0], sy + 9 * n[1]);
        ctx.moveTo(sx + 9 * n[0], sy + 9 * n[1]); ctx.arc(sx + 9 * n[0], sy + 9 * n[1], 1.5, 0, 2 * Math.PI);
      });
      ctx.stroke();
    }
    if (S.trace) drawTrace();
    if (S.hover) {
      const p = S.polys[S.hover.poly], k = p && p.ids.indexOf(S.hover.vertex);
      if (p && k >= 0) {
        const [x, y] = worldVertex(S.hover.poly, k);
        ctx.beginPath();
        ctx.arc(v.ox + x * v.scale, v.oy + y * v.scale, 6, 0, 2 * Math.PI);
        ctx.strokeStyle = "#000"; ctx.lineWidth = 1.5; ctx.stroke();
      }
    }
    S.dirty = false;
    S.drawMs = 0.9 * S.drawMs + 0.1 * (performance.now() - t0);
    figures();
  }
  // Each polygon's index (the step-through's P and Q) at its box centre, where the box
  // is at least 14 px wide on screen (smaller ones would be covered by their number).
  function drawNumbers() {
    const v = S.view;
    ctx.font = "11px system-ui, sans-serif"; ctx.textAlign = "center"; ctx.textBaseline = "middle";
    ctx.lineWidth = 3; ctx.strokeStyle = "rgba(255,255,255,0.85)"; ctx.fillStyle = "#1d2330";
    S.numbered = 0;
    for (let i = 0; i < S.polys.length; i++) {
      const b = worldBox(i);
      if ((b[2] - b[0]) * v.scale < 14) continue;
      const c = centre(i), x = v.ox + c[0] * v.scale, y = v.oy + c[1] * v.scale;
      ctx.strokeText(String(i), x, y); ctx.fillText(String(i), x, y);
      S.numbered++;
    }
  }
  // ---- step-through ----
  const ROLE = {
    triangle: "#1f7a3a", bound: "#7a5cc2", pencil: "#c27a00", window: "#d4a017", sample: "#0a7f8c",
    chain: "#1f7a3a", separator: "#111", witness: "#d0021b",
  };
  function onTrace(m) {
    S.trace = m; S.traceStep = 0; S.traces++;
    // Pause on the answer, not on the request: a refused trace leaves the motion alone.
    if (S.settings && !S.settings.paused) { S.resumeAfterTrace = true; send({ op: "settings", paused: true }); }
    status(`Trace of polygons ${m.polygons[0]} and ${m.polygons[1]} (${m.algorithm}): ${m.steps.length} steps; Close to leave it`, "ok");
    showTraceStep();
  }
  function showTraceStep() {
    const t = S.trace;
    if (!t) { $("traceText").textContent = ""; S.dirty = true; return; }
    const st = t.steps[S.traceStep];
    const last = S.traceStep === t.steps.length - 1;
    $("traceText").textContent = `${t.algorithm}, step ${S.traceStep + 1} of ${t.steps.length}: ${st.text}` +
      (last ? ` — certificate ${JSON.stringify(t.certificate).replace(/,/g, ", ")}` : "");
    S.dirty = true;
  }
  // The view of a trace: the box of its two polygons fitted to the canvas (with a margin),
  // so that small polygons in a large scene fill the picture.
  function traceView(t) {
    const b = bbox(Float64Array.from(t.p.concat(t.q).flat()));
    const r = canvas.getBoundingClientRect(), pad = 28;
    const w = Math.max(b[2] - b[0], 1e-300), h = Math.max(b[3] - b[1], 1e-300);
    const scale = Math.min((r.width - 2 * pad) / w, (r.height - 2 * pad) / h);
    return { scale, ox: (r.width - w * scale) / 2 - b[0] * scale, oy: (r.height - h * scale) / 2 - b[1] * scale, extent: w + h };
  }
  function drawTrace() {
    const t = S.trace, st = t.steps[S.traceStep], v = traceView(t);
    S.traceZoom = v.scale / S.view.scale;
    const X = (pt) => v.ox + pt[0] * v.scale, Y = (pt) => v.oy + pt[1] * v.scale;
    ctx.save();
    const r = canvas.getBoundingClientRect();
    // Only the pair: the scene is covered, not shown faintly behind.
    ctx.fillStyle = "#fbfcfe";
    ctx.fillRect(0, 0, r.width, r.height);
    ctx.fillStyle = "#566"; ctx.font = "12px system-ui, sans-serif"; ctx.textAlign = "left"; ctx.textBaseline = "top";
    ctx.fillText(`Zoomed on P = polygon ${t.polygons[0]} (blue) and Q = polygon ${t.polygons[1]} (red); Close returns to the scene`, 8, 6);
    const outline = (pts, colour, width, dash) => {
      ctx.beginPath();
      pts.forEach((pt, k) => (k ? ctx.lineTo(X(pt), Y(pt)) : ctx.moveTo(X(pt), Y(pt))));
      ctx.closePath(); ctx.setLineDash(dash || []); ctx.strokeStyle = colour; ctx.lineWidth = width; ctx.stroke();
    };
    const spans = (pts, list, colour, width, dash) => {
      for (const [start, len] of list) {
        ctx.beginPath();
        for (let k = 0; k < len; k++) {
          const pt = pts[(start + k) % pts.length];
          k ? ctx.lineTo(X(pt), Y(pt)) : ctx.moveTo(X(pt), Y(pt));
        }
        if (len === 1) { const pt = pts[start % pts.length]; ctx.arc(X(pt), Y(pt), 3, 0, 2 * Math.PI); }
        ctx.setLineDash(dash || []); ctx.strokeStyle = colour; ctx.lineWidth = width; ctx.stroke();
      }
    };
    outline(t.p, "#2d5a96", 1); outline(t.q, "#b3260d", 1);
    spans(t.p, st.pruned[0], "#9aa3b2", 3, [4, 3]); spans(t.q, st.pruned[1], "#9aa3b2", 3, [4, 3]);
    spans(t.p, st.kept[0], "#2d5a96", 3.5); spans(t.q, st.kept[1], "#b3260d", 3.5);
    const W = v.extent;
    for (const mk of st.marks) {
      const c = ROLE[mk.role] || "#000", pts = mk.points;
      ctx.setLineDash(mk.role === "bound" || mk.role === "window" ? [6, 4] : []);
      ctx.strokeStyle = c; ctx.fillStyle = c; ctx.lineWidth = mk.role === "separator" || mk.role === "witness" ? 2.5 : 1.5;
      ctx.beginPath();
      if (mk.kind === "points") {
        for (const pt of pts) { ctx.moveTo(X(pt) + 3, Y(pt)); ctx.arc(X(pt), Y(pt), 3, 0, 2 * Math.PI); }
        ctx.fill(); continue;
      }
      if (mk.kind === "line") {
        const [a, b] = pts, dx = b[0] - a[0], dy = b[1] - a[1], l = Math.hypot(dx, dy) || 1;
        const e = [dx / l * 2 * W, dy / l * 2 * W];
        ctx.moveTo(X([a[0] - e[0], a[1] - e[1]]), Y([a[0] - e[0], a[1] - e[1]]));
        ctx.lineTo(X([a[0] + e[0], a[1] + e[1]]), Y([a[0] + e[0], a[1] + e[1]]));
      } else {
        pts.forEach((pt, k) => (k ? ctx.lineTo(X(pt), Y(pt)) : ctx.moveTo(X(pt), Y(pt))));
        if (mk.kind === "polygon") ctx.closePath();
      }
      ctx.stroke();
    }
    ctx.restore();
  }
  function requestTrace() {
    if (!S.ready) return;
    send({ op: "trace", scene: S.scene, polygons: [Number($("traceA").value), Number($("traceB").value)], algorithm: $("traceAlgorithm").value });
  }
  function traceMove(d) {
    if (!S.trace) return;
    S.traceStep = Math.max(0, Math.min(S.trace.steps.length - 1, S.traceStep + d));
    showTraceStep();
  }

  // The world box: of the world points, else of the shape's box corners under the pose
  // (a box around the polygon, a little larger when it is turned).
  function worldBox(i) {
    const p = S.polys[i];
    if (p.w) return p.wbox;
    const b = p.box, corners = [toPose(i, b[0], b[1]), toPose(i, b[2], b[1]), toPose(i, b[2], b[3]), toPose(i, b[0], b[3])];
    return bbox(Float64Array.from(corners.flat()));
  }
  function centre(i) {
    const b = worldBox(i);
    return [(b[0] + b[2]) / 2, (b[1] + b[3]) / 2];
  }

  // At most four times a second (the DOM is slower than the canvas); tick() catches up.
  // Frames per second over the last second; 0 once no frame has moved for a second.
  function fps() {
    const last = S.times[S.times.length - 1];
    return last !== undefined && performance.now() - last < 1000 ? S.fps : 0;
  }

  function figures() {
    const now = performance.now();
    if (now - S.figuresAt < 250 || !S.last || (S.figuresOf === S.last && fps() > 0)) return;
    S.figuresAt = now;
    S.figuresOf = S.last;
    const m = S.last, t = m.timing, set = (id, x) => { $(id).textContent = x; };
    const f2 = (x) => x.toFixed(2);
    set("f-fps", fps().toFixed(1));
    set("f-total", f2(t.update_ms + t.broad_ms + t.narrow_ms + t.response_ms));
    set("f-update", f2(t.update_ms)); set("f-broad", f2(t.broad_ms)); set("f-narrow", f2(t.narrow_ms));
    set("f-response", f2(t.response_ms)); set("f-draw", f2(S.drawMs));
    set("f-queries", m.queries); set("f-box", m.stats.box_rejects);
    set("f-sampled", m.stats.sampled_tests); set("f-array", m.stats.array_tests);
    set("f-candidates", m.candidates); set("f-pairs", m.pairs.length);
    set("f-conversions", m.totals.conversions + m.totals.throwaway_conversions);
    set("f-sampledTotal", m.totals.sampled_tests);
    set("f-vertices", S.polys.reduce((a, p) => a + p.ids.length, 0));
    set("f-frame", m.frame);
  }

  function tick() {
    if (S.pending) { applyFrame(); draw(); requestFrame(); }
    else if (S.dirty) draw();
    else figures();
    requestAnimationFrame(tick);
  }

  // ---- controls ----
  // A new scene keeps the user's pause; one a trace made ends with the trace (onText).
  $("apply").onclick = () => send({ op: "settings", polygons: Number($("polygons").value), vertices: Number($("vertices").value), seed: Number($("seed").value) });
  $("strategy").onchange = (e) => send({ op: "settings", strategy: e.target.value });
  $("precision").onchange = (e) => send({ op: "settings", precision: e.target.value });
  $("speed").oninput = (e) => send({ op: "settings", speed: Number(e.target.value) });
  // The user's own choice overrides a pause the trace made.
  $("pause").onclick = () => { S.resumeAfterTrace = false; if (S.settings) send({ op: "settings", paused: !S.settings.paused }); };
  $("step").onclick = () => { if (S.ready && !S.inflight) { S.inflight = true; send({ op: "step" }); } };
  $("showVertices").onchange = () => { S.dirty = true; };
  $("showNormals").onchange = () => { S.dirty = true; };
  $("showNumbers").onchange = () => { S.dirty = true; };
  $("trace").onclick = requestTrace;
  $("traceBack").onclick = () => traceMove(-1);
  $("traceForward").onclick = () => traceMove(1);
  $("traceClose").onclick = () => { S.trace = null; showTraceStep(); resumeIfTracePaused(); };
  window.addEventListener("resize", resize);

  // What the page shows, for tests and the curious: the world coordinates drawn (the
  // store's own, sent with each frame; `exact` is false when some polygon is drawn from
  // its shape under the pose instead, e.g. in large scenes), the poses, the pairs drawn
  // as colliding, and whether the drawn pairs already account for every edit received.
  window.polysect = {
    get ready() { return S.ready; },
    // No frame requested and none waiting to be drawn.
    get idle() { return !S.inflight && !S.pending; },
    get scene() { return S.scene; },
    get world() { return S.world; },
    get frame() { return S.frame; },
    get fps() { return fps(); },
    get drawMs() { return S.drawMs; },
    get settings() { return S.settings; },
    get figures() { return S.last && { timing: S.last.timing, queries: S.last.queries, candidates: S.last.candidates, stats: S.last.stats, totals: S.last.totals }; },
    get refusals() { return S.refusals; },
    // Edits the page received as accepted.
    get edits() { return S.edits; },
    get lastRefusal() { return S.lastRefusal; },
    get errors() { return S.errors; },
    get lastError() { return S.lastError; },
    get status() { return $("status").textContent; },
    // The step-through: the trace received (null when closed) and the step shown.
    get trace() {
      const t = S.trace;
      return t && { algorithm: t.algorithm, polygons: t.polygons, steps: t.steps.length, step: S.traceStep,
        stepAnswer: t.steps[S.traceStep].answer, answer: t.answer, certificate: t.certificate, text: $("traceText").textContent,
        p: t.p, q: t.q };
    },
    get traces() { return S.traces; },
    // How many polygons carry their number on the canvas, and how much the last trace
    // drawn was magnified against the scene's view.
    get numbered() { return S.numbered; },
    get traceZoom() { return S.traceZoom; },
    shown() {
      return {
        scene: S.scene, frame: S.frame, pairs: S.pairs.map((p) => [p[0], p[1]]),
        // A frame of this scene drawn (before it, the page has shapes but no poses).
        consistent: S.last !== null && S.editsAtFrame === S.edits && !S.moveInflight,
        exact: S.polys.every((p) => p.w),
        poses: S.polys.map((_, i) => Array.from(S.poses.subarray(4 * i, 4 * i + 4))),
        polygons: S.polys.map((p, i) => {
          const out = [];
          for (let k = 0; k < p.ids.length; k++) out.push(worldVertex(i, k));
          return out;
        }),
        ids: S.polys.map((p) => Array.from(p.ids)),
      };
    },
    // Viewport coordinates (CSS pixels) of a world point.
    toScreen(x, y) {
      const r = canvas.getBoundingClientRect();
      return [r.left + S.view.ox + x * S.view.scale, r.top + S.view.oy + y * S.view.scale];
    },
  };

  resize();
  connect();
  requestAnimationFrame(tick);
})();
