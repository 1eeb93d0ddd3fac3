// The episode and motion viewer of `ropras view` (doc/viewer.md). Reads the document in #ropras-view (written by
// ropras::scenarios::episodeView / motionView) and draws it with three.js (THREE, THREE.OrbitControls), z up.
// After loading, #ropras-stats holds the counts of what it drew, the load time and the measured frame rate.
(function () {
  'use strict';
  var stats = document.getElementById('ropras-stats');

  function el(id) {
    return document.getElementById(id);
  }

  function fail(message) {
    window.roprasErrors.push(message);
    stats.dataset.errors = String(window.roprasErrors.length);
    stats.dataset.state = 'error';
    var box = el('ropras-error');
    box.style.display = 'block';
    box.textContent += message + '\n';
    console.error('ropras view: ' + message);
  }

  /** 1, 2 or 5 times a power of ten, near span / 10 (the grid step). */
  function niceStep(span) {
    var raw = span / 10;
    var p = Math.pow(10, Math.floor(Math.log10(raw)));
    var m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }

  /** A list of x, y, z triples: a plain array, or packed by the writer (ViewDocument::packed: uint16 levels per
      axis between origin and origin + 65535 * step, little-endian, base64). */
  function floats(v) {
    if (Array.isArray(v)) return new Float32Array(v);
    var text = atob(v.q16);
    var n = text.length >> 1;
    var out = new Float32Array(n);
    var o = v.origin, s = v.step;
    for (var i = 0, k = 0; i < n; i++, k = k === 2 ? 0 : k + 1) {
      out[i] = o[k] + s[k] * (text.charCodeAt(2 * i) | (text.charCodeAt(2 * i + 1) << 8));
    }
    return out;
  }

  function material(colour, opacity) {
    return new THREE.MeshLambertMaterial({
      color: new THREE.Color(colour),
      transparent: opacity < 0.99,
      opacity: opacity,
      depthWrite: opacity >= 0.99
    });
  }

  function Viewer(view) {
    this.view = view;
    this.frames = Math.max(1, view.frames | 0);
    this.frame = 0;
    this.playing = false;
    this.position = 0;
    this.counts = { boxes: 0, spheres: 0, cylinders: 0, bodies: 0, bodySpheres: 0, paths: 0, particles: 0,
      snapshots: 0, maxParticles: 0, rays: 0, frames: this.frames };
    this.bounds = new THREE.Box3();  // everything
    this.moving = new THREE.Box3();  // what moves (the camera frames it when the document has no bounds)
    this.legend = [];
    this.dynamic = [];
  }

  Viewer.prototype.build = function () {
    THREE.Object3D.DefaultUp.set(0, 0, 1);
    var view = this.view;
    var scene = this.scene = new THREE.Scene();
    scene.background = new THREE.Color('#eef1f4');
    scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 0.75));
    var sun = new THREE.DirectionalLight(0xffffff, 0.55);
    sun.position.set(0.4, -0.6, 1.0);
    scene.add(sun);

    var layers = (view.layers || []).map(function (layer) {
      var group = new THREE.Group();
      group.name = layer.name;
      scene.add(group);
      return { group: group, material: material(layer.colour, layer.opacity), info: layer };
    });
    var unitBox = new THREE.BoxBufferGeometry(1, 1, 1);
    var unitSphere = new THREE.SphereBufferGeometry(1, 20, 14);
    var unitCylinder = new THREE.CylinderBufferGeometry(1, 1, 1, 24);
    unitCylinder.rotateX(Math.PI / 2);  // three.js cylinders run along y; ours along z
    var self = this;
    function add(layerIndex, geometry, position, scale, q) {
      var layer = layers[layerIndex];
      var mesh = new THREE.Mesh(geometry, layer.material);
      mesh.position.set(position[0], position[1], position[2]);
      mesh.scale.set(scale[0], scale[1], scale[2]);
      if (q) mesh.quaternion.set(q[0], q[1], q[2], q[3]);
      layer.group.add(mesh);
      mesh.updateMatrixWorld(true);
      self.bounds.expandByObject(mesh);
    }
    (view.boxes || []).forEach(function (b) {
      add(b[0], unitBox, [b[1], b[2], b[3]], [b[4], b[5], b[6]], [b[7], b[8], b[9], b[10]]);
      self.counts.boxes++;
    });
    (view.spheres || []).forEach(function (s) {
      add(s[0], unitSphere, [s[1], s[2], s[3]], [s[4], s[4], s[4]]);
      self.counts.spheres++;
    });
    (view.cylinders || []).forEach(function (c) {
      add(c[0], unitCylinder, [c[1], c[2], c[3]], [c[4], c[4], c[5]], [c[6], c[7], c[8], c[9]]);
      self.counts.cylinders++;
    });
    layers.forEach(function (layer) {
      if (layer.group.children.length) self.legend.push({ name: layer.info.name, colour: layer.info.colour,
        objects: [layer.group] });
    });
    if (view.bounds) {
      var lo = view.bounds[0], hi = view.bounds[1];
      this.bounds.expandByPoint(new THREE.Vector3(lo[0], lo[1], lo[2]));
      this.bounds.expandByPoint(new THREE.Vector3(hi[0], hi[1], hi[2]));
      var frame = new THREE.Box3Helper(new THREE.Box3(new THREE.Vector3(lo[0], lo[1], lo[2]),
        new THREE.Vector3(hi[0], hi[1], hi[2])), new THREE.Color('#333333'));
      scene.add(frame);
    }
    this.buildBodies(unitSphere);
    this.buildPaths();
    this.buildBeliefs();
    this.buildRays();
    this.buildGround();
  };

  Viewer.prototype.buildBodies = function (unitSphere) {
    var self = this;
    this.bodies = (this.view.bodies || []).map(function (body) {
      var count = body.radii.length;
      var mesh = new THREE.InstancedMesh(unitSphere, material(body.colour, 1.0), Math.max(1, count));
      mesh.count = count;
      mesh.frustumCulled = false;
      self.scene.add(mesh);
      self.counts.bodies++;
      self.counts.bodySpheres += count;
      // the body's extent over all frames, for the camera
      var c = floats(body.centres);
      for (var i = 0; i + 2 < c.length; i += 3) {
        var v = new THREE.Vector3(c[i], c[i + 1], c[i + 2]);
        self.bounds.expandByPoint(v);
        self.moving.expandByPoint(v);
      }
      self.legend.push({ name: body.name, colour: body.colour, objects: [mesh] });
      return { mesh: mesh, radii: body.radii, centres: c, count: count };
    });
  };

  Viewer.prototype.buildPaths = function () {
    var self = this;
    this.paths = (this.view.paths || []).map(function (path) {
      var geometry = new THREE.BufferGeometry();
      var xyz = floats(path.points);
      geometry.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
      var all = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: path.colour, transparent: true,
        opacity: 0.3 }));
      var done = new THREE.Line(geometry.clone(), new THREE.LineBasicMaterial({ color: path.colour }));
      self.scene.add(all);
      self.scene.add(done);
      self.counts.paths++;
      self.legend.push({ name: path.label + ' path', colour: path.colour, objects: [all, done] });
      return { line: done, points: xyz.length / 3 };
    });
  };

  Viewer.prototype.buildBeliefs = function () {
    var self = this;
    this.beliefs = (this.view.beliefs || []).map(function (belief) {
      var geometry = new THREE.BufferGeometry();
      var xyz = floats(belief.points);
      geometry.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
      var points = new THREE.Points(geometry, new THREE.PointsMaterial({ color: belief.colour, size: 4,
        sizeAttenuation: false, transparent: true, opacity: 0.65, depthWrite: false }));
      points.frustumCulled = false;
      self.scene.add(points);
      self.counts.snapshots = Math.max(self.counts.snapshots, belief.steps.length);
      self.counts.particles += xyz.length / 3;
      for (var i = 0; i + 1 < belief.offsets.length; i++) {
        self.counts.maxParticles = Math.max(self.counts.maxParticles, belief.offsets[i + 1] - belief.offsets[i]);
      }
      self.legend.push({ name: belief.label + ' belief', colour: belief.colour, objects: [points] });
      return { points: points, snapshot: self.snapshotIndex(belief.steps), offsets: belief.offsets };
    });
  };

  /** For every frame, the index of the snapshot with the largest step <= frame (-1 before the first). */
  Viewer.prototype.snapshotIndex = function (steps) {
    var order = steps.map(function (s, i) { return i; }).sort(function (a, b) { return steps[a] - steps[b]; });
    var index = new Int32Array(this.frames).fill(-1);
    var k = -1;
    for (var f = 0; f < this.frames; f++) {
      while (k + 1 < order.length && steps[order[k + 1]] <= f) k++;
      index[f] = k < 0 ? -1 : order[k];
    }
    return index;
  };

  Viewer.prototype.buildRays = function () {
    var rays = this.view.rays;
    this.rays = null;
    if (!rays || !rays.steps || !rays.steps.length) return;
    var geometry = new THREE.BufferGeometry();
    var xyz = floats(rays.segments);
    geometry.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
    var lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: '#f9a825' }));
    lines.frustumCulled = false;
    this.scene.add(lines);
    this.counts.rays = xyz.length / 6;
    this.legend.push({ name: 'rays', colour: '#f9a825', objects: [lines] });
    this.rays = { lines: lines, snapshot: this.snapshotIndex(rays.steps), offsets: rays.offsets };
  };

  /** A grid on the floor with a metric step, and the world axes (x red, y green, z blue) one step long. */
  Viewer.prototype.buildGround = function () {
    var size = this.bounds.getSize(new THREE.Vector3());
    var centre = this.bounds.getCenter(new THREE.Vector3());
    var span = Math.max(size.x, size.y, 1e-3);
    var step = this.gridStep = niceStep(span);
    var cells = Math.ceil(span / step) + 2;
    var grid = new THREE.GridHelper(cells * step, cells, 0x9aa5b1, 0xc8d0d8);
    grid.rotateX(Math.PI / 2);
    grid.position.set(Math.round(centre.x / step) * step, Math.round(centre.y / step) * step,
      this.bounds.isEmpty() ? 0 : this.bounds.min.z - 1e-3 * span);
    this.scene.add(grid);
    var axes = new THREE.AxesHelper(step);
    this.scene.add(axes);
    this.legend.push({ name: 'grid ' + step + ' m, axes', colour: '#9aa5b1', objects: [grid, axes] });
  };

  Viewer.prototype.setFrame = function (frame) {
    var f = Math.max(0, Math.min(this.frames - 1, frame | 0));
    this.frame = f;
    var matrix = new THREE.Matrix4();
    var q = new THREE.Quaternion();
    var p = new THREE.Vector3();
    var s = new THREE.Vector3();
    this.bodies.forEach(function (body) {
      var base = f * body.count * 3;
      if (base + body.count * 3 > body.centres.length) return;
      for (var i = 0; i < body.count; i++) {
        p.set(body.centres[base + 3 * i], body.centres[base + 3 * i + 1], body.centres[base + 3 * i + 2]);
        s.setScalar(Math.max(body.radii[i], 1e-4));
        matrix.compose(p, q, s);
        body.mesh.setMatrixAt(i, matrix);
      }
      body.mesh.instanceMatrix.needsUpdate = true;
    });
    this.paths.forEach(function (path) {
      path.line.geometry.setDrawRange(0, Math.min(path.points, f + 1));
    });
    this.beliefs.forEach(function (belief) {
      var k = belief.snapshot[f];
      if (k < 0) belief.points.geometry.setDrawRange(0, 0);
      else belief.points.geometry.setDrawRange(belief.offsets[k], belief.offsets[k + 1] - belief.offsets[k]);
    });
    if (this.rays) {
      var k = this.rays.snapshot[f];
      if (k < 0) this.rays.lines.geometry.setDrawRange(0, 0);
      else this.rays.lines.geometry.setDrawRange(2 * this.rays.offsets[k],
        2 * (this.rays.offsets[k + 1] - this.rays.offsets[k]));
    }
    el('ropras-frame').value = String(f);
    el('ropras-time').textContent = (this.view.frame_label || 'frame') + ' ' + f + ' / ' + (this.frames - 1);
    this.dirty = true;
  };

  Viewer.prototype.start = function (container) {
    // #noaa turns antialiasing off (software renderers draw about twice as fast without it)
    var antialias = !/[#&]noaa/.test(location.hash);
    var renderer = this.renderer = new THREE.WebGLRenderer({ antialias: antialias, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(window.innerWidth, window.innerHeight);
    container.appendChild(renderer.domElement);
    var camera = this.camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight, 1e-3, 1e5);
    var frame = this.bounds.clone();
    if (!this.view.bounds && !this.moving.isEmpty()) {
      frame = this.moving.clone().expandByScalar(0.25 * this.moving.getSize(new THREE.Vector3()).length());
      frame.intersect(this.bounds);
    }
    var centre = frame.isEmpty() ? new THREE.Vector3() : frame.getCenter(new THREE.Vector3());
    var radius = frame.isEmpty() ? 1 : Math.max(1e-3, frame.getSize(new THREE.Vector3()).length() / 2);
    var flat = this.view.dims === 2;
    var direction = flat ? new THREE.Vector3(0, -0.55, 1) : new THREE.Vector3(1.1, -1.4, 0.9);
    camera.position.copy(centre).add(direction.normalize().multiplyScalar(radius * 2.3));
    camera.near = radius / 1000;
    camera.far = radius * 100;
    camera.updateProjectionMatrix();
    var controls = this.controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.copy(centre);
    controls.update();
    var self = this;
    controls.addEventListener('change', function () { self.dirty = true; });
    window.addEventListener('resize', function () {
      camera.aspect = window.innerWidth / window.innerHeight;
      camera.updateProjectionMatrix();
      renderer.setSize(window.innerWidth, window.innerHeight);
      self.dirty = true;
    });
  };

  Viewer.prototype.buildUi = function () {
    var self = this;
    el('ropras-title').textContent = this.view.title || 'ropras view';
    el('ropras-subtitle').textContent = this.view.subtitle || '';
    var slider = el('ropras-frame');
    slider.max = String(this.frames - 1);
    slider.addEventListener('input', function () {
      self.position = Number(slider.value);
      self.setFrame(self.position);
    });
    var play = el('ropras-play');
    function toggle() {
      self.playing = !self.playing;
      if (self.playing && self.frame >= self.frames - 1) self.position = 0;
      play.innerHTML = self.playing ? '&#10074;&#10074; pause' : '&#9654; play';
    }
    play.addEventListener('click', toggle);
    window.addEventListener('keydown', function (e) {
      if (e.key === ' ') { toggle(); e.preventDefault(); }
      if (e.key === 'ArrowRight') { self.position = self.frame + 1; self.setFrame(self.position); }
      if (e.key === 'ArrowLeft') { self.position = self.frame - 1; self.setFrame(self.position); }
    });
    var legend = el('ropras-legend');
    this.legend.forEach(function (entry) {
      var label = document.createElement('label');
      var box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = true;
      box.addEventListener('change', function () {
        entry.objects.forEach(function (o) { o.visible = box.checked; });
        self.dirty = true;
      });
      var swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = entry.colour;
      label.appendChild(box);
      label.appendChild(swatch);
      label.appendChild(document.createTextNode(entry.name));
      legend.appendChild(label);
    });
  };

  /** Draws when something changed (a new frame, the camera moved); while playing, the rate of the drawn frames
      is reported each second in #ropras-stats data-play-fps and in the panel. */
  Viewer.prototype.loop = function () {
    var self = this;
    var last = performance.now();
    var windowStart = last, drawn = 0;
    var speed = el('ropras-speed');
    function tick(now) {
      var dt = Math.min(0.25, Math.max(0, (now - last) / 1000));
      last = now;
      if (self.playing) {
        self.position += dt * Number(speed.value) / (self.view.frame_seconds || 0.1);
        if (self.position >= self.frames - 1) {
          self.position = self.frames - 1;
          el('ropras-play').click();
        }
        if ((self.position | 0) !== self.frame) self.setFrame(self.position);
        self.dirty = true;
      }
      if (self.dirty) {
        self.renderer.render(self.scene, self.camera);
        self.dirty = false;
        drawn++;
      }
      if (!self.playing) {
        windowStart = now;
        drawn = 0;
      } else if (now - windowStart >= 1000) {
        var fps = 1000 * drawn / (now - windowStart);
        stats.dataset.playFps = fps.toFixed(1);
        el('ropras-rate').textContent = fps.toFixed(0) + ' frames/s';
        windowStart = now;
        drawn = 0;
      }
      requestAnimationFrame(tick);
    }
    requestAnimationFrame(tick);
  };

  /** #measure: renders 60 frames of the animation back to back, each waited for (gl.finish), and reports the
      rate: what the browser can draw per second, independent of the display's refresh. */
  Viewer.prototype.measure = function (frames) {
    var gl = this.renderer.getContext();
    var begin = performance.now();
    for (var i = 0; i < frames; i++) {
      this.setFrame(Math.floor(i * (this.frames - 1) / Math.max(1, frames - 1)));
      this.renderer.render(this.scene, this.camera);
      gl.finish();
    }
    var fps = frames / Math.max(1e-3, (performance.now() - begin) / 1000);
    stats.dataset.drawFps = fps.toFixed(1);
    this.setFrame(this.position);
    this.renderer.render(this.scene, this.camera);
    return fps;
  };

  try {
    var times = [performance.now()];
    var view = JSON.parse(el('ropras-view').textContent);
    times.push(performance.now());
    var viewer = new Viewer(view);
    window.roprasViewer = viewer;
    viewer.build();
    times.push(performance.now());
    viewer.start(el('ropras-canvas'));
    viewer.buildUi();
    var first = /[#&]frame=(\d+)/.exec(location.hash);
    viewer.position = first ? Number(first[1]) : viewer.frames - 1;
    viewer.setFrame(viewer.position);
    if (/[#&]play/.test(location.hash)) el('ropras-play').click();
    times.push(performance.now());
    viewer.renderer.render(viewer.scene, viewer.camera);
    times.push(performance.now());
    // milliseconds: before this script (the page and three.js), JSON, scene, WebGL context and UI, first picture
    stats.dataset.scriptStartMs = times[0].toFixed(0);
    stats.dataset.parseMs = (times[1] - times[0]).toFixed(0);
    stats.dataset.buildMs = (times[2] - times[1]).toFixed(0);
    stats.dataset.contextMs = (times[3] - times[2]).toFixed(0);
    stats.dataset.renderMs = (times[4] - times[3]).toFixed(0);
    var c = viewer.counts;
    Object.keys(c).forEach(function (key) { stats.dataset[key] = String(c[key]); });
    stats.dataset.loadMs = (performance.now()).toFixed(0);
    stats.dataset.gridStep = String(viewer.gridStep);
    if (stats.dataset.state !== 'error') stats.dataset.state = 'ready';
    el('ropras-info').textContent = c.frames + ' frames, ' + (c.boxes + c.spheres + c.cylinders) + ' shapes, ' +
      c.bodySpheres + ' moving spheres' + (c.particles ? ', ' + c.maxParticles + ' particles per snapshot' : '') +
      '; loaded in ' + stats.dataset.loadMs + ' ms';
    viewer.loop();
    if (/[#&]measure/.test(location.hash)) {
      setTimeout(function () {
        el('ropras-info').textContent += ', draws ' + viewer.measure(60).toFixed(0) + ' frames/s';
      }, 0);
    }
  } catch (e) {
    fail(String(e && e.message ? e.message : e));
  }
})();
