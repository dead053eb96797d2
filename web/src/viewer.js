// The viewer on the page's side: the canvas, the camera and its orbit/zoom/pan controls, fitting,
// and a proxy to the render worker (render/render_worker.js), which owns WebGL through an
// OffscreenCanvas. The page's thread does camera math only, so drawing never blocks it.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export class Viewer {
  constructor(container) {
    this.container = container;
    this.canvas = document.createElement('canvas');
    container.appendChild(this.canvas);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.camera.position.set(0, 0, 5);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = true;
    this.controls.addEventListener('change', () => this.sendCamera());
    this.snapshot = null; // {kinds, version} of the model shown (hover highlighting)
    this.bounds = null;   // THREE.Box3 of the model (mesh units)
    this.surfaceBounds = null;
    this.showFaces = false;
    this.showSurface = false;
    this.showMirror = true;
    this.mirrorPlane = null; // {axis: 0..2, at} (Zome units) of the model shown when it is mirror-symmetric
    this.pending = new Map();
    this.nextId = 1;
    this.pickMesh = null; // the surface on this thread, for clicks (the render worker has its own copy)
    this.onPick = null;   // (point [x, y, z], mesh units) after a click on the surface
    this.pointerDown = null;
    this.canvas.addEventListener('pointerdown', (e) => { this.pointerDown = { x: e.clientX, y: e.clientY }; });
    this.canvas.addEventListener('pointerup', (e) => {
      const d = this.pointerDown;
      this.pointerDown = null;
      // A click, not the end of a drag that turned the model.
      if (!d || Math.hypot(e.clientX - d.x, e.clientY - d.y) > 4 || !this.onPick) return;
      const point = this.pick(e.clientX, e.clientY);
      if (point) this.onPick(point);
    });

    const offscreen = this.canvas.transferControlToOffscreen();
    this.worker = new Worker(new URL('./render/render_worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = ({ data }) => {
      const entry = this.pending.get(data.id);
      if (!entry) return;
      this.pending.delete(data.id);
      if (data.error) entry.reject(new Error(data.error));
      else entry.resolve(data.result);
    };
    const { width, height } = this.size();
    this.worker.postMessage({ type: 'init', canvas: offscreen, width, height,
      pixelRatio: Math.min(window.devicePixelRatio, 2) }, [offscreen]);
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    const tick = () => {
      this.controls.update(); // damping; emits 'change' while the camera moves
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  size() {
    return { width: Math.max(1, this.container.clientWidth), height: Math.max(1, this.container.clientHeight) };
  }

  resize() {
    const { width, height } = this.size();
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.worker.postMessage({ type: 'resize', width, height });
    this.sendCamera();
  }

  sendCamera() {
    const c = this.camera;
    this.worker.postMessage({ type: 'camera', position: c.position.toArray(), quaternion: c.quaternion.toArray(),
      fov: c.fov, aspect: c.aspect, near: c.near, far: c.far });
  }

  /** Shows a snapshot (protocol.js Snapshot; its buffers are handed to the render worker). */
  setModel(snapshot, { fit = false } = {}) {
    const { positions, scale, translation } = snapshot;
    const box = new THREE.Box3();
    const p = new THREE.Vector3(), t = new THREE.Vector3().fromArray(translation);
    for (let i = 0; i < positions.length; i += 3) box.expandByPoint(p.fromArray(positions, i).multiplyScalar(scale).add(t));
    this.bounds = box.isEmpty() ? null : box;
    this.snapshot = { kinds: snapshot.kinds.slice(), version: snapshot.version };
    const transfer = [snapshot.positions.buffer, snapshot.struts.buffer, snapshot.kinds.buffer, snapshot.triangles.buffer];
    this.worker.postMessage({ type: 'model', snapshot }, transfer);
    if (fit) this.fit();
  }

  /** The point of the input surface under a click (client pixels), or null. */
  pick(clientX, clientY) {
    if (!this.pickMesh) return null;
    const r = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    const hit = ray.intersectObject(this.pickMesh, false)[0];
    return hit ? hit.point.toArray() : null;
  }

  /** The input surface (mesh units), drawn translucent when shown; null removes it. */
  setSurface(surface) {
    this.surfaceBounds = null;
    this.pickMesh = null;
    if (surface) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(surface.positions.slice(), 3));
      geometry.setIndex(new THREE.BufferAttribute(surface.triangles.slice(), 1));
      this.pickMesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ side: THREE.DoubleSide }));
      const box = new THREE.Box3(), p = new THREE.Vector3();
      for (let i = 0; i < surface.positions.length; i += 3) box.expandByPoint(p.fromArray(surface.positions, i));
      this.surfaceBounds = box;
      this.worker.postMessage({ type: 'surface', surface }, [surface.positions.buffer, surface.triangles.buffer]);
    } else {
      this.worker.postMessage({ type: 'surface', surface: null });
    }
  }

  setFacesVisible(on) {
    this.showFaces = on;
    this.sendVisibility();
  }

  setSurfaceVisible(on) {
    this.showSurface = on;
    this.sendVisibility();
  }

  setMirrorVisible(on) {
    this.showMirror = on;
    this.sendVisibility();
  }

  sendVisibility() {
    this.worker.postMessage({ type: 'visibility', faces: this.showFaces, surface: this.showSurface,
      mirror: this.showMirror });
  }

  /** The mirror plane of a symmetric model ({axis: 0..2, at}, Zome units), drawn translucent; null removes it. */
  setMirrorPlane(plane) {
    this.mirrorPlane = plane;
    this.worker.postMessage({ type: 'mirrorPlane', plane });
  }

  /** Highlights the struts whose kind is in `kindIds` (numbers 0..8); null restores the colours. */
  highlightKinds(kindIds) {
    this.worker.postMessage({ type: 'highlight', kinds: kindIds });
  }

  /**
   * The Build view's colouring: per strut and per ball the step that adds it (Int32Array), and the
   * step shown; null restores the model's colours.
   */
  showBuildStep(state) {
    this.worker.postMessage({ type: 'buildStep', state });
  }

  /** Frames the model (or the surface when there is no model). */
  fit() {
    const box = this.bounds || this.surfaceBounds;
    if (!box) return;
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const distance = Math.max(sphere.radius, 1e-6) / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) * 1.05;
    const view = new THREE.Vector3(0.55, 0.45, 1).normalize();
    this.camera.position.copy(sphere.center).addScaledVector(view, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(sphere.center);
    this.controls.update();
    this.sendCamera();
  }

  /** Promise of the fractions of canvas pixels in each strut colour (tests and the API use it). */
  colourCoverage() {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.worker.postMessage({ type: 'coverage', id });
    });
  }
}
