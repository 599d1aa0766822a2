/* viewer.js — pathlab's image viewer, embedded into every page that `pathlab view`, compare and grade
 * write (src/image/html_page.c). No library, no network: everything the page shows is in the page.
 *
 * The page holds:
 *   <script type="application/json" id="pathlab-settings">  {title, w, h, images:[...], ref, strip:[...], marks:[...]}
 *     each image is {name, link, rgb: id, sd: id or null}
 *   <script type="application/octet-stream" id="pathlab-rgb-N">  base64 of little-endian half floats,
 *     3 per pixel (R, G, B), row 0 = the top row; "pathlab-sd-N" the standard deviation of each
 *     pixel's mean (the square root of pathlab's variance image), for the probe's z-score. A compact
 *     page (enc "rgbe85": grade's pages of large images) holds RGBE pixels in base 85 and no sd.
 *
 * The images are decoded once into Float32Arrays; the canvas is redrawn (one ImageData) only when
 * something that changes its pixels changes (exposure, gamma, mode, image, channels, split). Zoom and
 * pan only move the canvas (a CSS transform, nearest-pixel display), so a 2048x1024 image stays smooth.
 *
 * window.pathlabViewer is a small API for tests (tests/viewer/) and for the curious, in the console. */
(function () {
  'use strict';
  var started = performance.now();
  var settings = JSON.parse(document.getElementById('pathlab-settings').textContent);
  var W = settings.w, H = settings.h, N = W * H;

  /* ---------- decoding ---------- */

  /* A half float's value, from its 16 bits (IEEE 754 binary16). */
  function halfToFloat(h) {
    var sign = h & 0x8000 ? -1 : 1, e = (h >> 10) & 31, m = h & 1023;
    if (e === 0) return sign * m * Math.pow(2, -24);              // subnormal (or zero)
    if (e === 31) return m ? NaN : sign * Infinity;
    return sign * (1 + m / 1024) * Math.pow(2, e - 15);
  }
  /* All 65536 halves once: decoding is then one table look-up per value. */
  var HALF = new Float32Array(65536);
  for (var h = 0; h < 65536; h++) HALF[h] = halfToFloat(h);

  /* The Float32Array of one data block (by id), or null. atob skips the line breaks. */
  function decode(id) {
    if (!id) return null;
    var block = document.getElementById(id), bin = atob(block.textContent);
    block.remove();   // the text is no longer needed: the page's memory drops by its size
    var n = bin.length >> 1, out = new Float32Array(n);
    for (var i = 0; i < n; i++) out[i] = HALF[bin.charCodeAt(2 * i) | (bin.charCodeAt(2 * i + 1) << 8)];
    return out;
  }
  /* A compact page's image (src/image/html_page.c, max_bytes): RGBE pixels, 4 bytes each (big-endian)
   * as 5 base-85 digits of B85; read as (m + 0.5) 2^(e - 136), Ward's centring. Line breaks skipped. */
  var B85 = "#$%'()*+,-./0123456789:;=?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[]^_`abcdefghijklmnopqrstuvwxyz{";
  var DIGIT = new Int16Array(128).fill(-1), EXP = new Float32Array(256);
  for (var d = 0; d < 85; d++) DIGIT[B85.charCodeAt(d)] = d;
  for (var e = 1; e < 256; e++) EXP[e] = Math.pow(2, e - 136);
  function decodeRgbe85(id) {
    var block = document.getElementById(id), text = block.textContent, out = new Float32Array(3 * N);
    var w = 0, nd = 0, p = 0;
    block.remove();
    for (var i = 0; i < text.length && p < N; i++) {
      var v = DIGIT[text.charCodeAt(i) & 127];
      if (v < 0) continue;
      w = w * 85 + v;
      if (++nd < 5) continue;
      var ex = w % 256, f = EXP[ex];
      out[3 * p] = ex ? (Math.floor(w / 16777216) + 0.5) * f : 0;
      out[3 * p + 1] = ex ? (Math.floor(w / 65536) % 256 + 0.5) * f : 0;
      out[3 * p + 2] = ex ? (Math.floor(w / 256) % 256 + 0.5) * f : 0;
      p++; w = 0; nd = 0;
    }
    return out;
  }
  function load(desc) {
    if (!desc) return null;
    return { name: desc.name, link: desc.link, rgb: desc.enc === 'rgbe85' ? decodeRgbe85(desc.rgb) : decode(desc.rgb), sd: decode(desc.sd) };
  }
  var images = settings.images.map(load);
  var ref = load(settings.ref);
  var strip = settings.strip.map(load);
  /* What the keys cycle through: the images, then the reference. */
  var views = ref ? images.concat([ref]) : images.slice();

  /* ---------- automatic ranges ---------- */

  /* The q-quantile of f(i) over (at most 65536 evenly spread) pixels i, ignoring non-finite values.
   * A Float32Array sorts numerically and some ten times faster than an Array of numbers. */
  function quantile(f, q) {
    var step = Math.max(1, Math.floor(N / 65536)), vals = new Float32Array(Math.ceil(N / step)), n = 0;
    for (var i = 0; i < N; i += step) { var v = f(i); if (isFinite(v)) vals[n++] = v; }
    if (!n) return 0;
    vals = vals.subarray(0, n).sort();
    return vals[Math.min(n - 1, Math.floor(q * n))];
  }
  /* The exposure (stops, to 0.1) that brings the median luminance of the pixels that are not black
   * to mid-grey, 0.18: the rule of pathlab convert --exposure auto (src/image/exposure.h), which
   * shows a layer's surfaces, not its brightest emitter. */
  function autoExposure(im) {
    var p = quantile(function (i) {
      var y = 0.2126 * im.rgb[3 * i] + 0.7152 * im.rgb[3 * i + 1] + 0.0722 * im.rgb[3 * i + 2];
      return y > 0 ? y : NaN;
    }, 0.5);
    return p > 0 ? Math.round(Math.log2(0.18 / p) * 10) / 10 : 0;
  }
  /* The difference's full scale: the 99th percentile of |image - reference| (mean of R, G, B). */
  function autoDiffScale(im) {
    if (!ref) return 1;
    var p = quantile(function (i) { return Math.abs(signedDiff(im, i)); }, 0.99);
    return p > 0 ? p : 1;
  }

  /* ---------- state ---------- */

  var st = {
    cur: 0,                 // index into views
    exposure: autoExposure(images[0]),
    gamma: 0,               // 0: the sRGB curve; else value^(1/gamma)
    mode: 'image',          // 'image', 'split' (image left, reference right) or 'diff'
    split: 0.5,             // the divide, as a fraction of the width
    ch: [true, true, true], // channel toggles
    diffScale: 1,
    zoom: 1, panX: 0, panY: 0,
    row: H >> 1, rowFixed: false, mouseX: -1
  };
  st.diffScale = autoDiffScale(images[0]);

  /* ---------- tone mapping ---------- */

  var LUT_SIZE = 16384, lut = new Uint8ClampedArray(LUT_SIZE + 1);
  /* Linear [0,1] -> 8 bits, through the sRGB curve or a plain gamma. */
  function encode8(v) {
    var e = st.gamma > 0 ? Math.pow(v, 1 / st.gamma) : (v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055);
    return Math.round(255 * e);
  }
  function buildLut() { for (var i = 0; i <= LUT_SIZE; i++) lut[i] = encode8(i / LUT_SIZE); }
  /* A linear value, already multiplied by 2^exposure, as drawn: negative and NaN black, >= 1 white. */
  function tone(v) { return v > 0 ? (v >= 1 ? 255 : lut[Math.round(v * LUT_SIZE)]) : 0; }
  buildLut();

  /* The mean over the enabled channels of image - reference at pixel i. */
  function signedDiff(im, i) {
    var s = 0, n = 0;
    for (var c = 0; c < 3; c++) if (st.ch[c]) { s += im.rgb[3 * i + c] - ref.rgb[3 * i + c]; n++; }
    return n ? s / n : 0;
  }
  /* Signed false colour of d: black at 0; image brighter than the reference red -> yellow, darker
   * blue -> cyan; full at |d| = diffScale. The square root lifts small differences into sight. */
  function diffColour(d, out, o) {
    var t = Math.sqrt(Math.min(1, Math.abs(d) / st.diffScale)) * 2;
    var hot = Math.min(1, t) * 255, warm = Math.max(0, t - 1) * 255;
    out[o] = d > 0 ? hot : 0; out[o + 1] = warm; out[o + 2] = d < 0 ? hot : 0; out[o + 3] = 255;
  }
  /* One pixel of image im, tone-mapped into out[o..o+3]; with one channel enabled it is shown grey. */
  function imageColour(im, i, k, out, o) {
    var on = st.ch[0] + st.ch[1] + st.ch[2];
    for (var c = 0; c < 3; c++) out[o + c] = st.ch[c] ? tone(im.rgb[3 * i + c] * k) : 0;
    if (on === 1) { var g = out[o] + out[o + 1] + out[o + 2]; out[o] = out[o + 1] = out[o + 2] = g; }
    out[o + 3] = 255;
  }

  /* ---------- the page's elements ---------- */

  function el(tag, cls, parent, text) {
    var e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  var root = document.getElementById('pathlab-viewer');
  var bar = el('div', 'pl-bar', root);
  var tabs = el('span', 'pl-tabs', bar);
  var controls = el('span', 'pl-controls', bar);
  var view = el('div', 'pl-view', root);
  view.tabIndex = 0;
  var stage = el('div', 'pl-stage', view);
  var canvas = el('canvas', 'pl-main', stage);
  canvas.width = W; canvas.height = H;
  var ctx = canvas.getContext('2d');
  var imageData = ctx.createImageData(W, H);
  var divide = el('div', 'pl-divide', stage);
  var rowLine = el('div', 'pl-row', stage);
  var info = el('pre', 'pl-info', root, ' ');
  var plot = el('canvas', 'pl-plot', root);
  var stripBox = el('div', 'pl-strip', root);
  el('p', 'pl-help', root, 'keys: \u2190 \u2192 or n p the images, 1-9 one image, i image, s split, d difference, ' +
     'r g b channels, + - exposure, a automatic exposure, f fit, 0 one image pixel per screen pixel; ' +
     'wheel zooms, drag pans (in split view, drag the divide); click fixes the plotted row');

  /* The bar: a tab per image (its label a link when it has one), then the controls. */
  function buildTabs() {
    views.forEach(function (im, k) {
      var b = el('button', 'pl-tab', tabs, (k < 9 ? (k + 1) + ' ' : '') + im.name + (im === ref ? ' (reference)' : ''));
      b.onclick = function () { setImage(k); };
      if (im.link) { var a = el('a', 'pl-link', tabs, '\u2197'); a.href = im.link; a.title = 'open ' + im.link; }
    });
  }
  function control(label, input) { var l = el('label', null, controls, label); l.appendChild(input); return input; }
  function input(type, attrs) { var e = document.createElement('input'); e.type = type; for (var k in attrs) e[k] = attrs[k]; return e; }
  var ui = {};
  function buildControls() {
    ui.modes = ['image', 'split', 'diff'].map(function (m) {
      var b = el('button', 'pl-mode', controls, m === 'diff' ? 'difference' : m);
      b.onclick = function () { setMode(m); };
      b.disabled = m !== 'image' && !ref;
      b.dataset.mode = m;
      return b;
    });
    ui.exposure = control('exposure ', input('range', { min: -20, max: 20, step: 0.1 }));
    ui.exposure.oninput = function () { st.exposure = +ui.exposure.value; redrawSoon(); };
    ui.expText = el('span', 'pl-num', controls);
    el('button', null, controls, 'auto').onclick = function () { setExposure(autoExposure(views[st.cur])); };
    ui.gamma = control(' gamma ', el('select'));
    [['sRGB', 0], ['1.0 (linear)', 1], ['1.8', 1.8], ['2.2', 2.2]].forEach(function (g) {
      var o = el('option', null, ui.gamma, g[0]); o.value = g[1];
    });
    ui.gamma.onchange = function () { setGamma(+ui.gamma.value); };
    ui.ch = ['R', 'G', 'B'].map(function (name, c) {
      var box = control(' ' + name, input('checkbox', { checked: true }));
      box.onchange = function () { st.ch[c] = box.checked; redraw(); };
      return box;
    });
    ui.diff = control(' difference scale ', input('number', { step: 'any', min: 0 }));
    ui.diff.onchange = function () { if (+ui.diff.value > 0) { st.diffScale = +ui.diff.value; redraw(); } };
    el('button', null, controls, 'fit').onclick = fit;
  }

  /* ---------- drawing ---------- */

  /* The main canvas from the state: one pass over the pixels into one ImageData. */
  function redraw() {
    var out = imageData.data, im = views[st.cur], k = Math.pow(2, st.exposure);
    var splitX = Math.round(st.split * W), mode = ref ? st.mode : 'image';
    if (mode !== 'diff' && st.ch[0] && st.ch[1] && st.ch[2]) fastImage(out, im, k, mode === 'split' ? splitX : W);
    else
      for (var y = 0, i = 0; y < H; y++)
        for (var x = 0; x < W; x++, i++) {
          if (mode === 'diff') diffColour(signedDiff(im, i), out, 4 * i);
          else imageColour(mode === 'split' && x >= splitX ? ref : im, i, k, out, 4 * i);
        }
    ctx.putImageData(imageData, 0, 0);
    syncControls();
    drawPlot();
  }
  /* The usual case written out (the same as imageColour with every channel on): im left of column
   * splitX, the reference right of it; about twice as fast as a call per pixel. */
  function fastImage(out, im, k, splitX) {
    for (var y = 0, i = 0; y < H; y++)
      for (var x = 0; x < W; x++, i++) {
        var a = x < splitX ? im.rgb : ref.rgb, o = 4 * i, j = 3 * i;
        var r = a[j] * k, g = a[j + 1] * k, b = a[j + 2] * k;
        out[o] = r > 0 ? (r >= 1 ? 255 : lut[Math.round(r * LUT_SIZE)]) : 0;
        out[o + 1] = g > 0 ? (g >= 1 ? 255 : lut[Math.round(g * LUT_SIZE)]) : 0;
        out[o + 2] = b > 0 ? (b >= 1 ? 255 : lut[Math.round(b * LUT_SIZE)]) : 0;
        out[o + 3] = 255;
      }
  }
  /* Many slider events a second: one redraw per animation frame at most. */
  var pending = false;
  function redrawSoon() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(function () { pending = false; redraw(); });
  }

  /* The controls show the state (after a key or an API call changed it). */
  function syncControls() {
    ui.exposure.value = st.exposure;
    ui.expText.textContent = (st.exposure >= 0 ? '+' : '') + st.exposure.toFixed(1);
    ui.diff.value = +st.diffScale.toPrecision(3);
    ui.modes.forEach(function (b) { b.classList.toggle('pl-on', b.dataset.mode === st.mode); });
    Array.prototype.forEach.call(tabs.querySelectorAll('.pl-tab'), function (b, k) { b.classList.toggle('pl-on', k === st.cur); });
    ui.ch.forEach(function (b, c) { b.checked = st.ch[c]; });
    divide.style.display = st.mode === 'split' && ref ? 'block' : 'none';
    divide.style.left = (st.split * W) + 'px';
  }
  /* Zoom and pan: only the stage moves. Borders are divided by the zoom to stay thin on screen. */
  function place() {
    stage.style.transform = 'translate(' + st.panX + 'px,' + st.panY + 'px) scale(' + st.zoom + ')';
    root.style.setProperty('--pl-px', (1 / st.zoom) + 'px');
    rowLine.style.top = st.row + 'px';
    layoutLabels();
  }
  function fit() {
    var vw = view.clientWidth, vh = view.clientHeight;
    st.zoom = Math.min(64, Math.min(vw / W, vh / H));
    st.panX = (vw - W * st.zoom) / 2; st.panY = (vh - H * st.zoom) / 2;
    st.fitted = true;   // a resized window fits again, until the user zooms or pans
    place();
  }

  /* The marks (grade's significant regions): outlined boxes with their labels, over the image. */
  var labels = [];
  function buildMarks() {
    settings.marks.forEach(function (m) {
      var box = el('div', 'pl-mark', stage);
      box.style.left = m.x + 'px'; box.style.top = m.y + 'px';
      box.style.width = m.w + 'px'; box.style.height = m.h + 'px';
      box.title = m.label;
      labels.push({ m: m, span: el('span', 'pl-mark-label', box, m.label) });
    });
  }
  /* The labels inside the image and clear of each other. Each tries above its box, inside its top,
   * below it, inside its bottom, then down the image from the top, always shifted left to end within
   * the image; the first place that meets no label already placed wins, and a label with no such
   * place is hidden (its box keeps the text as a tooltip). Their size follows the zoom (--pl-px),
   * so they are placed again at every zoom. */
  function layoutLabels() {
    var placed = [];
    var gap = 1 / st.zoom;   // one screen pixel between labels
    function free(x, y, w, h) {
      return !placed.some(function (r) { return x < r.x + r.w + gap && r.x < x + w + gap && y < r.y + r.h + gap && r.y < y + h + gap; });
    }
    labels.forEach(function (L) {
      var m = L.m, s = L.span, w, h, x, y = null, k, tries;
      s.style.display = '';
      var b = s.getBoundingClientRect();   // on screen: divided by the zoom, in image pixels (offsetWidth rounds)
      w = b.width / st.zoom; h = b.height / st.zoom;
      x = Math.max(0, Math.min(m.x, W - w));
      tries = [m.y - h, m.y, m.y + m.h, m.y + m.h - h];
      for (k = 0; h > 0 && k * h / 2 <= H; k++) tries.push(k * h / 2);
      for (k = 0; k < tries.length && y === null; k++) {
        var c = Math.max(0, Math.min(tries[k], H - h));
        if (free(x, c, w, h)) y = c;
      }
      if (y === null || w > W) { s.style.display = 'none'; return; }
      placed.push({ x: x, y: y, w: w, h: h });
      var bw = 2 / st.zoom;   // the box's border (viewer.css): the label is placed from inside it
      s.style.left = (x - m.x - bw) + 'px'; s.style.top = (y - m.y - bw) + 'px'; s.style.bottom = 'auto';
    });
  }

  /* The strip: one small canvas per layer (L0, L1...), each at its own automatic exposure. */
  function drawLayer(s) {
    var c = s.canvas.getContext('2d'), d = c.createImageData(W, H), k = Math.pow(2, s.exposure);
    for (var i = 0; i < N; i++) imageColour(s.im, i, k, d.data, 4 * i);
    c.putImageData(d, 0, 0);
  }
  var layers = strip.map(function (im) {
    var fig = el('figure', 'pl-layer', stripBox), s = { im: im, exposure: autoExposure(im) };
    s.canvas = el('canvas', null, fig); s.canvas.width = W; s.canvas.height = H;
    var cap = el('figcaption', null, fig, im.name + ' ');
    s.input = input('number', { step: 0.5, value: s.exposure, title: 'exposure (stops)' });
    cap.appendChild(s.input);
    s.input.onchange = function () { s.exposure = +s.input.value; drawLayer(s); };
    return s;
  });

  /* ---------- the probe and the scanline plot ---------- */

  function triple(a, i) { return a ? [a[3 * i], a[3 * i + 1], a[3 * i + 2]] : null; }
  /* Everything known about pixel (x, y) of the current image: value, reference, difference, z. */
  function probe(x, y) {
    if (x < 0 || y < 0 || x >= W || y >= H) return null;
    var i = y * W + x, im = views[st.cur], p = { x: x, y: y, name: im.name, value: triple(im.rgb, i) };
    if (!ref || im === ref) return p;
    p.ref = triple(ref.rgb, i);
    p.diff = p.value.map(function (v, c) { return v - p.ref[c]; });
    if (im.sd || ref.sd) p.z = p.diff.map(function (d, c) {
      var a = im.sd ? im.sd[3 * i + c] : 0, b = ref.sd ? ref.sd[3 * i + c] : 0;
      return d / Math.sqrt(a * a + b * b);
    });
    return p;
  }
  function fmt(v) { return v === undefined || v === null ? '-' : (+v).toPrecision(4); }
  function showProbe(x, y) {
    var p = probe(x, y);
    if (!p) { info.textContent = ' '; return; }
    var t = '(' + x + ', ' + y + ')  ' + p.name + ' ' + p.value.map(fmt).join(' ');
    if (p.ref) t += '   reference ' + p.ref.map(fmt).join(' ') + '   difference ' + p.diff.map(fmt).join(' ');
    if (p.z) t += '   z ' + p.z.map(function (z) { return isFinite(z) ? z.toFixed(2) : '-'; }).join(' ');
    info.textContent = t;
  }

  /* The row st.row of the current image (solid) and of the reference (dashed), R G B, linear values. */
  function drawPlot() {
    var pw = plot.clientWidth || 600, ph = 140, c = plot.getContext('2d'), im = views[st.cur], top = 0;
    plot.width = pw; plot.height = ph;
    [im, ref].forEach(function (s) {
      if (s) for (var x = 0; x < W; x++) for (var ch = 0; ch < 3; ch++) {
        var v = s.rgb[3 * (st.row * W + x) + ch]; if (st.ch[ch] && isFinite(v) && v > top) top = v;
      }
    });
    top = top > 0 ? top * 1.05 : 1;
    c.fillStyle = '#111'; c.fillRect(0, 0, pw, ph);
    ['#f44', '#4d4', '#48f'].forEach(function (colour, ch) {
      if (!st.ch[ch]) return;
      [im, ref !== im ? ref : null].forEach(function (s, dashed) {
        if (!s) return;
        c.strokeStyle = colour; c.setLineDash(dashed ? [4, 3] : []); c.beginPath();
        for (var x = 0; x < W; x++) c.lineTo((x + 0.5) * pw / W, ph - 4 - (ph - 8) * s.rgb[3 * (st.row * W + x) + ch] / top);
        c.stroke();
      });
    });
    c.setLineDash([]); c.fillStyle = '#ccc';
    c.fillText('row ' + st.row + (st.rowFixed ? ' (fixed)' : '') + '   0 .. ' + top.toPrecision(3), 6, 12);
    if (st.mouseX >= 0) { c.strokeStyle = '#888'; c.beginPath(); c.moveTo((st.mouseX + 0.5) * pw / W, 0); c.lineTo((st.mouseX + 0.5) * pw / W, ph); c.stroke(); }
  }

  /* ---------- mouse and keys ---------- */

  function imagePoint(ev) {
    var r = view.getBoundingClientRect();
    return { x: (ev.clientX - r.left - st.panX) / st.zoom, y: (ev.clientY - r.top - st.panY) / st.zoom };
  }
  var drag = null;
  view.addEventListener('mousedown', function (ev) {
    var p = imagePoint(ev), nearDivide = Math.abs(p.x - st.split * W) * st.zoom < 8;
    drag = { divide: st.mode === 'split' && ref && nearDivide, x: ev.clientX, y: ev.clientY, moved: false };
    ev.preventDefault(); view.focus();
  });
  window.addEventListener('mouseup', function (ev) {
    if (drag && !drag.moved && !drag.divide) {   // a click: fix (or free) the plotted row
      var p = imagePoint(ev); st.rowFixed = !st.rowFixed; st.row = Math.max(0, Math.min(H - 1, Math.floor(p.y)));
      place(); drawPlot();
    }
    drag = null;
  });
  view.addEventListener('mousemove', function (ev) {
    var p = imagePoint(ev), x = Math.floor(p.x), y = Math.floor(p.y);
    if (drag) {
      if (Math.abs(ev.clientX - drag.x) + Math.abs(ev.clientY - drag.y) > 2) drag.moved = true;
      if (drag.divide) { setSplit(p.x / W); return; }
      st.panX += ev.clientX - drag.x; st.panY += ev.clientY - drag.y; drag.x = ev.clientX; drag.y = ev.clientY;
      st.fitted = false; place(); return;
    }
    showProbe(x, y);
    st.mouseX = x >= 0 && x < W ? x : -1;
    if (!st.rowFixed && y >= 0 && y < H) { st.row = y; place(); }
    drawPlot();
  });
  view.addEventListener('wheel', function (ev) {
    var r = view.getBoundingClientRect(), mx = ev.clientX - r.left, my = ev.clientY - r.top;
    var z = Math.max(1 / 16, Math.min(64, st.zoom * Math.pow(2, ev.deltaY < 0 ? 0.25 : -0.25)));
    st.panX = mx - (mx - st.panX) * z / st.zoom; st.panY = my - (my - st.panY) * z / st.zoom; st.zoom = z;   // the point under the mouse stays
    st.fitted = false; place(); ev.preventDefault();
  }, { passive: false });

  var KEYS = {
    ArrowRight: function () { setImage(st.cur + 1); }, n: function () { setImage(st.cur + 1); },
    ArrowLeft: function () { setImage(st.cur - 1); }, p: function () { setImage(st.cur - 1); },
    i: function () { setMode('image'); }, s: function () { setMode('split'); }, d: function () { setMode('diff'); },
    r: function () { toggle(0); }, g: function () { toggle(1); }, b: function () { toggle(2); },
    '+': function () { setExposure(st.exposure + 0.5); }, '=': function () { setExposure(st.exposure + 0.5); },
    '-': function () { setExposure(st.exposure - 0.5); }, a: function () { setExposure(autoExposure(views[st.cur])); },
    f: fit, 0: function () { st.zoom = 1; st.fitted = false; place(); }
  };
  document.addEventListener('keydown', function (ev) {
    if (ev.target.tagName === 'INPUT' || ev.target.tagName === 'SELECT' || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    if (KEYS[ev.key]) KEYS[ev.key]();
    else if (ev.key >= '1' && ev.key <= '9') setImage(+ev.key - 1);
    else return;
    ev.preventDefault();
  });

  /* ---------- the state's setters (the controls, the keys and the test API use them) ---------- */

  function setImage(k) {
    st.cur = ((k % views.length) + views.length) % views.length;
    if (ref && views[st.cur] !== ref) st.diffScale = autoDiffScale(views[st.cur]);
    redraw();
  }
  function setMode(m) { if (m === 'image' || ref) { st.mode = m; redraw(); } }
  function setExposure(s) { st.exposure = Math.max(-40, Math.min(40, +s)); redraw(); }
  function setGamma(g) { st.gamma = g === 'srgb' ? 0 : +g; ui.gamma.value = st.gamma; buildLut(); redraw(); layers.forEach(drawLayer); }
  function setSplit(f) { st.split = Math.max(0, Math.min(1, f)); redraw(); }
  function toggle(c) { st.ch[c] = !st.ch[c]; redraw(); }

  buildTabs();
  buildControls();
  buildMarks();
  fit();
  redraw();
  layers.forEach(drawLayer);
  window.addEventListener('resize', function () { if (st.fitted) fit(); });
  document.title = settings.title || document.title;

  window.pathlabViewer = {
    width: W, height: H,
    loadMs: performance.now() - started,   // decoding and the first drawing
    probe: probe,
    showProbe: showProbe,   // as if the mouse were over pixel (x, y): the line of values, the plotted row
    setRow: function (y) { st.row = y; st.rowFixed = true; place(); drawPlot(); },
    /* zoom z (screen pixels per image pixel) centred on the image point (x, y) */
    setView: function (z, x, y) {
      st.zoom = z; st.panX = view.clientWidth / 2 - x * z; st.panY = view.clientHeight / 2 - y * z; st.fitted = false; place();
    },
    displayedPixel: function (x, y) { var o = 4 * (y * W + x), d = imageData.data; return [d[o], d[o + 1], d[o + 2]]; },
    setExposure: setExposure, exposure: function () { return st.exposure; },
    autoExposure: function () { return autoExposure(views[st.cur]); },
    setGamma: setGamma, setSplit: setSplit, setMode: setMode, setImage: setImage,
    setChannels: function (r, g, b) { st.ch = [!!r, !!g, !!b]; redraw(); },
    setDiffScale: function (s) { st.diffScale = s; redraw(); },
    current: function () { return views[st.cur].name; },
    stripCount: function () { return stripBox.querySelectorAll('canvas').length; },
    stripExposure: function (k) { return layers[k].exposure; },
    stripPixel: function (k, x, y) {
      var d = layers[k].canvas.getContext('2d').getImageData(x, y, 1, 1).data; return [d[0], d[1], d[2]];
    },
    marks: function () { return stage.querySelectorAll('.pl-mark').length; },
    key: function (k) { document.dispatchEvent(new KeyboardEvent('keydown', { key: k })); },
    redrawMs: function () { var t = performance.now(); redraw(); return performance.now() - t; }
  };
})();
