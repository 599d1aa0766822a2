/* tests/viewer/test.js — appended (by tests/test_viewer.sh) to a copy of a page that `pathlab view`
 * wrote, after the viewer's own script; drives window.pathlabViewer and writes "PASS ..." / "FAIL ..."
 * lines into <pre id="pathlab-test">, which the shell reads from Chromium's --dump-dom.
 * The expected values come from the PFM files themselves (PFM.image, PFM.ref, ... : the files' bytes
 * in base64, set by the shell before this script), parsed here with a DataView: a decoding path
 * independent of pathlab's half floats and of the viewer's decoder.
 * TEST.kind says which page this is: "main" (images, reference, variances, layers), "marks" (load
 * time of 2048x1024 images, marks and links: the page of build/tests/test_html_page). */
(function () {
  'use strict';
  var out = [], V = window.pathlabViewer;
  function pass(name) { out.push('PASS viewer: ' + name); }
  function fail(name, why) { out.push('FAIL viewer: ' + name + ': ' + why); }
  function check(name, ok, why) { if (ok) pass(name); else fail(name, why); }
  function finish() {
    var pre = document.createElement('pre');
    pre.id = 'pathlab-test';
    pre.textContent = '\n' + out.join('\n') + '\n';
    document.body.appendChild(pre);
  }

  /* A PFM file (base64) -> {w, h, px: Float32Array, row 0 = the top row}. */
  function parsePfm(b64) {
    var bin = atob(b64), bytes = new Uint8Array(bin.length), pos = 0, fields = [];
    for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    while (fields.length < 4) {   // "PF", w, h, scale, each ended by one whitespace
      var s = '';
      while (!/\s/.test(bin[pos])) s += bin[pos++];
      pos++;
      fields.push(s);
    }
    var w = +fields[1], h = +fields[2], little = +fields[3] < 0, dv = new DataView(bytes.buffer, pos);
    var px = new Float32Array(3 * w * h);
    for (var y = 0; y < h; y++)            // PFM rows go bottom to top
      for (var k = 0; k < 3 * w; k++) px[3 * w * (h - 1 - y) + k] = dv.getFloat32(4 * (3 * w * y + k), little);
    return { w: w, h: h, px: px };
  }
  function value(img, x, y, c) { return img.px[3 * (y * img.w + x) + c]; }
  /* within half-float precision: relative 1e-3, or 3e-8 absolute (half subnormals near 0) */
  function close(a, b, rel) { return Math.abs(a - b) <= (rel || 1e-3) * Math.abs(b) + 3e-8; }
  function srgb8(v) {
    v = Math.max(0, Math.min(1, v));
    return Math.round(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055));
  }
  function near(a, b, tol) { return a.every(function (v, c) { return Math.abs(v - b[c]) <= tol; }); }

  try {
    if (!V) { fail('the test API', 'window.pathlabViewer is missing (the viewer script failed?)'); return finish(); }
    if (TEST.kind === 'main') mainTests();
    if (TEST.kind === 'marks') { bigTests(); marksTests(); }
  } catch (e) {
    fail('the test script', 'threw ' + e + ' ' + (e.stack || ''));
  }
  networkTests();

  /* The probe at chosen pixels: the image's, the reference's values, the difference and the z-score. */
  function probeTests(img, ref, vimg, vref, pixels) {
    var bad = [];
    pixels.forEach(function (p) {
      var q = V.probe(p[0], p[1]);
      for (var c = 0; c < 3; c++) {
        var a = value(img, p[0], p[1], c), r = value(ref, p[0], p[1], c);
        var z = (q.value[c] - q.ref[c]) / Math.sqrt(value(vimg, p[0], p[1], c) + value(vref, p[0], p[1], c));
        if (!close(q.value[c], a)) bad.push('value ' + p + '/' + c + ' ' + q.value[c] + ' vs ' + a);
        if (!close(q.ref[c], r)) bad.push('ref ' + p + '/' + c + ' ' + q.ref[c] + ' vs ' + r);
        if (Math.abs(q.diff[c] - (q.value[c] - q.ref[c])) > 1e-6) bad.push('diff ' + p + '/' + c);
        if (!(Math.abs(q.z[c] - z) <= 2e-3 * Math.abs(z) + 1e-6) && !(isNaN(z) && isNaN(q.z[c])))   // 0/0 where both are black
          bad.push('z ' + p + '/' + c + ' ' + q.z[c] + ' vs ' + z);
      }
    });
    return bad;
  }

  function mainTests() {
    var img = parsePfm(PFM.image), ref = parsePfm(PFM.ref), small = parsePfm(PFM.small);
    var vimg = parsePfm(PFM.image_var), vref = parsePfm(PFM.ref_var), W = img.w, H = img.h;
    var pixels = [[0, 0], [W - 1, 0], [0, H - 1], [W - 1, H - 1], [W >> 1, 1], [W >> 1, H >> 1], [17, 41], [W - 9, 23], [30, 50], [60, 12]];
    check('size ' + V.width + 'x' + V.height, V.width === W && V.height === H, 'the PFM is ' + W + 'x' + H);
    var bad = probeTests(img, ref, vimg, vref, pixels);
    check('probe: value, reference, difference, z-score at ' + pixels.length + ' pixels equal the PFMs\' (relative 1e-3)',
          !bad.length, bad.slice(0, 4).join('; '));
    /* the second image: the first x 1e-3 (half floats' small and subnormal range) */
    V.setImage(1);
    bad = [];
    pixels.forEach(function (p) {
      var q = V.probe(p[0], p[1]);
      for (var c = 0; c < 3; c++) if (!close(q.value[c], value(small, p[0], p[1], c))) bad.push(p + '/' + c + ' ' + q.value[c] + ' vs ' + value(small, p[0], p[1], c));
    });
    check('probe: the second image (values x 1e-3) within 1e-3 relative + 3e-8', !bad.length, bad.slice(0, 4).join('; '));
    V.setImage(0);
    exposureTests(img);
    var lums = [];
    for (var i = 0; i < W * H; i++) {
      var y = 0.2126 * img.px[3 * i] + 0.7152 * img.px[3 * i + 1] + 0.0722 * img.px[3 * i + 2];
      if (y > 0) lums.push(y);
    }
    lums.sort(function (a, b) { return a - b; });
    var auto = Math.log2(0.18 / lums[lums.length >> 1]);
    check('exposure: automatic, the median luminance of the pixels not black to 0.18 (' + V.autoExposure() + ' stops, from the PFM ' +
          auto.toFixed(3) + ', convert --exposure auto ' + TEST.convertAuto + ')',
          Math.abs(V.autoExposure() - auto) <= 0.1 && Math.abs(V.autoExposure() - TEST.convertAuto) <= 0.1, V.autoExposure() + ' vs ' + auto);
    channelTests(img);
    splitTests(img, ref);
    diffTests(img, ref);
    keyTests();
    check('strip: one canvas per layer (3: L0, L1, L2)', V.stripCount() === 3, V.stripCount() + ' canvases');
    var e = [0, 1, 2].map(V.stripExposure);
    check('strip: each layer at its own exposure (' + e.join(', ') + ')', e[0] !== e[1] && e[1] !== e[2], 'the same exposures');
    var L1 = parsePfm(PFM.layer1), k1 = Math.pow(2, e[1]);
    bad = [];
    pixels.forEach(function (p) {
      var want = [0, 1, 2].map(function (c) { return srgb8(value(L1, p[0], p[1], c) * k1); }), got = V.stripPixel(1, p[0], p[1]);
      if (!near(got, want, 1)) bad.push(p + ': ' + got + ' vs ' + want);
    });
    check('strip: L1 drawn from c_L1.pfm at its exposure (' + pixels.length + ' pixels within 1)', !bad.length, bad.slice(0, 3).join('; '));
  }

  /* The displayed pixels follow the exposure: x 2 a stop in linear display, the sRGB curve otherwise. */
  function exposureTests(img) {
    var bad = [], s = V.exposure(), checked = 0;
    V.setMode('image');
    V.setChannels(1, 1, 1);
    V.setGamma(1);   // linear display: 8-bit values proportional to the pixel's
    for (var y = 0; y < img.h; y += 7) for (var x = 0; x < img.w; x += 5) {
      V.setExposure(s);
      var a = V.displayedPixel(x, y), r = value(img, x, y, 0) * Math.pow(2, s);
      if (!(r > 0.1 && r < 0.45)) continue;
      V.setExposure(s + 1);
      var b = V.displayedPixel(x, y);
      checked++;
      if (Math.abs(b[0] - 2 * a[0]) > 2 || Math.abs(a[0] - Math.round(255 * r)) > 1) bad.push(x + ',' + y + ': ' + a[0] + ' -> ' + b[0] + ' (' + r + ')');
      if (checked >= 12) break;
    }
    check('exposure: +1 stop doubles ' + checked + ' displayed values (linear display)', checked >= 5 && !bad.length,
          checked + ' pixels checked; ' + bad.slice(0, 3).join('; '));
    V.setGamma('srgb');
    V.setExposure(s - 1.5);
    bad = [];
    [[3, 3], [W2(img), 10], [20, 30]].forEach(function (p) {
      var want = [0, 1, 2].map(function (c) { return srgb8(value(img, p[0], p[1], c) * Math.pow(2, s - 1.5)); });
      var got = V.displayedPixel(p[0], p[1]);
      if (!near(got, want, 1)) bad.push(p + ': ' + got + ' vs ' + want);
    });
    check('exposure: sRGB display equals 255 srgb(v 2^s) within 1', !bad.length, bad.join('; '));
    V.setExposure(s);
  }
  /* Channel toggles: R alone is shown grey (its value in all three), R and G alone leave blue black.
   * At a pixel of the back wall under the light, lit whatever the 8 samples (the dim (30, 50) was
   * black with the sampler's numbers by use). */
  function channelTests(img) {
    var p = [48, 20], want = expected(img, p[0], p[1]);
    V.setChannels(1, 0, 0); var red = V.displayedPixel(p[0], p[1]);
    V.setChannels(1, 1, 0); var rg = V.displayedPixel(p[0], p[1]);
    V.setChannels(1, 1, 1);
    check('channels: R alone grey ' + red + ', R and G ' + rg + ' (all: ' + want + ')',
          near(red, [want[0], want[0], want[0]], 1) && near(rg, [want[0], want[1], 0], 1) && want[2] > 0, 'expected ' + want);
  }
  function W2(img) { return img.w >> 1; }
  function expected(img, x, y) {
    var k = Math.pow(2, V.exposure());
    return [0, 1, 2].map(function (c) { return srgb8(value(img, x, y, c) * k); });
  }

  /* Split: the image left of the divide, the reference right of it; moving the divide moves it. */
  function splitTests(img, ref) {
    var W = img.w, H = img.h, left = [], right = [], bad = [];
    V.setMode('split');
    V.setSplit(0.5);
    for (var y = 0; y < H; y += 3) for (var x = 0; x < W; x += 3) {
      var a = expected(img, x, y), b = expected(ref, x, y);
      if (Math.abs(a[1] - b[1]) < 6) continue;   // a pixel where the two images differ visibly
      (x < W / 2 ? left : right).push([x, y, a, b]);
    }
    left.slice(0, 10).forEach(function (p) { if (!near(V.displayedPixel(p[0], p[1]), p[2], 1)) bad.push('left ' + p[0] + ',' + p[1]); });
    right.slice(0, 10).forEach(function (p) { if (!near(V.displayedPixel(p[0], p[1]), p[3], 1)) bad.push('right ' + p[0] + ',' + p[1]); });
    check('split: the image left of the divide, the reference right (' + Math.min(10, left.length) + ' + ' + Math.min(10, right.length) + ' pixels)',
          left.length >= 3 && right.length >= 3 && !bad.length, left.length + '/' + right.length + ' pixels; ' + bad.slice(0, 4).join('; '));
    V.setSplit(0.25);
    bad = [];
    left.filter(function (p) { return p[0] >= W / 4; }).slice(0, 10).forEach(function (p) {
      if (!near(V.displayedPixel(p[0], p[1]), p[3], 1)) bad.push(p[0] + ',' + p[1]);
    });
    check('split: dragged to 1/4, the pixels between show the reference', !bad.length, bad.slice(0, 4).join('; '));
    V.setMode('image');
  }

  /* The difference: image brighter than the reference red (no blue), darker blue (no red). */
  function diffTests(img, ref) {
    var pos = 0, neg = 0, bad = [];
    V.setMode('diff');
    for (var y = 0; y < img.h; y += 2) for (var x = 0; x < img.w; x += 2) {
      var d = 0;
      for (var c = 0; c < 3; c++) d += (value(img, x, y, c) - value(ref, x, y, c)) / 3;
      var px = V.displayedPixel(x, y);
      if (Math.abs(d) < 5e-3 || px[0] + px[2] < 40) continue;   // too small to be sure of the sign after half rounding
      if (d > 0) { pos++; if (!(px[0] > 0 && px[2] === 0)) bad.push('+ at ' + x + ',' + y + ': ' + px); }
      else { neg++; if (!(px[2] > 0 && px[0] === 0)) bad.push('- at ' + x + ',' + y + ': ' + px); }
    }
    check('difference: ' + pos + ' brighter pixels red, ' + neg + ' darker blue', pos >= 5 && neg >= 5 && !bad.length,
          pos + '/' + neg + ' pixels; ' + bad.slice(0, 4).join('; '));
    V.setMode('image');
  }

  /* Keys: right arrow to the next image, number keys to one, d to the difference view. */
  function keyTests() {
    V.key('ArrowRight'); var a = V.current();
    V.key('3'); var b = V.current();
    V.key('n'); var c = V.current();
    V.key('1'); var before = V.displayedPixel(40, 30); V.key('d'); var px = V.displayedPixel(40, 30); V.key('i');
    check('keys: -> n.pfm-small, 3 the reference, n back to the first (' + [a, b, c].join(', ') + ')',
          a === 'small.pfm' && b === 'r.pfm' && c === 'c.pfm', 'got ' + [a, b, c].join(', '));
    check('keys: d shows the difference (red or blue, not both; ' + before + ' -> ' + px + ')',
          (px[0] === 0 || px[2] === 0) && !near(px, before, 0), 'pixel ' + before + ' -> ' + px);
  }

  function bigTests() {
    check('2048x1024: decoded and drawn in ' + V.loadMs.toFixed(0) + ' ms (bound ' + TEST.bound + ' ms)',
          V.width === 2048 && V.height === 1024 && V.loadMs < TEST.bound, V.width + 'x' + V.height + ', ' + V.loadMs.toFixed(0) + ' ms');
    var t = V.redrawMs(); V.setExposure(V.exposure() + 1); V.setMode('image');
    check('2048x1024: one redraw (exposure changed) in ' + t.toFixed(0) + ' ms (bound 1000 ms)', t < 1000, t.toFixed(0) + ' ms');
  }

  /* The compact page (RGBE in base 85): its values within half an RGBE step (1/512 of 2^e, the
   * largest channel in [2^(e-1), 2^e)) of test_html_page's pattern, at a few pixels. */
  function compactTests() {
    var worst = 0;
    [[0, 0], [7, 3], [100, 200], [2047, 1023], [1500, 77]].forEach(function (xy) {
      var v = V.probe(xy[0], xy[1]).value, want = [0, 1, 2].map(function (c) {
        return Math.pow(10, 3 * Math.sin(0.01 * xy[0] + c) * Math.cos(0.013 * xy[1]));
      }), top = Math.max.apply(null, want);
      want.forEach(function (w, c) { worst = Math.max(worst, Math.abs(v[c] - w) / top); });
    });
    check('compact page: values within half an RGBE step of the largest channel (worst ' + worst.toExponential(2) + ')', worst <= 1 / 256, worst);
  }

  function marksTests() {
    compactTests();
    check('marks: 3 regions outlined', V.marks() === 3, V.marks() + ' marks');
    var img = document.querySelector('.pl-main').getBoundingClientRect();
    var rects = Array.prototype.map.call(document.querySelectorAll('.pl-mark-label'), function (e) { return e.getBoundingClientRect(); });
    var outside = rects.filter(function (r) { return r.left < img.left - 1 || r.right > img.right + 1 || r.top < img.top - 1 || r.bottom > img.bottom + 1; });
    var overlaps = 0;
    rects.forEach(function (a, i) { rects.slice(i + 1).forEach(function (b) { overlaps += a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5; }); });
    check('marks: every label inside the image (one at its right edge, one at its top)', outside.length === 0 && rects.length === 3, outside.length + ' outside of ' + rects.length + ': ' + outside.map(function (r) { return [r.left, r.top, r.right, r.bottom].map(Math.round).join(','); }).join(' ') + ' image ' + [img.left, img.top, img.right, img.bottom].map(Math.round).join(','));
    check('marks: no two labels overlap', overlaps === 0, overlaps + ' overlapping pairs');
    var labels = Array.prototype.map.call(document.querySelectorAll('.pl-mark-label'), function (e) { return e.textContent; });
    check('marks: labels shown as text (escaped): ' + labels.join(' | '), labels[1] === 'too dark <b>', labels.join(' | '));
    var link = document.querySelector('.pl-link');
    check('links: the image label links to its page', link && link.getAttribute('href') === 'alice.html', link ? link.getAttribute('href') : 'no link');
    check('before/after HTML placed around the viewer', document.getElementById('verdict') && document.getElementById('notes'), 'missing');
  }

  /* No request at all: no resource fetched, no blocked attempt (CSP reports), once the page is loaded.
   * A control first: an image from https://192.0.2.1 must be seen blocked, else the check is blind. */
  function networkTests() {
    var blocked = [];
    document.addEventListener('securitypolicyviolation', function (e) { blocked.push(e.blockedURI); });
    var probeImg = new Image();
    probeImg.src = 'https://192.0.2.1/control.png';
    setTimeout(function () {
      var control = blocked.filter(function (u) { return u.indexOf('192.0.2.1') >= 0; }).length;
      var others = (window.__pathlabBlocked || []).concat(blocked).filter(function (u) { return u.indexOf('192.0.2.1') < 0; });
      var res = performance.getEntriesByType('resource').filter(function (r) { return r.name.indexOf('192.0.2.1') < 0; });
      check('network: the control request was blocked by the page\'s CSP', control >= 1, 'no violation seen for the control');
      var dataImage = document.getElementById('data-image');
      if (TEST.kind === 'marks')
        check('an image from html_data_uri shown (4x3 SVG)', dataImage && dataImage.naturalWidth === 4 && dataImage.naturalHeight === 3,
              dataImage ? dataImage.naturalWidth + 'x' + dataImage.naturalHeight : 'no image');
      check('network: no resource loaded, no request blocked', others.length === 0 && res.length === 0,
            others.concat(res.map(function (r) { return r.name; })).join(' '));
      finish();
    }, 200);
  }
})();
