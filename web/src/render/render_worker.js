// The render worker: three.js draws the model into an OffscreenCanvas here, so a slow rasteriser
// (software WebGL on a busy CPU) holds up this thread, never the page's. The page owns the camera
// (orbit controls) and sends its pose; the scene is drawn only when something changed.
// Imported by path, not by the bare name: import maps do not reach workers (vite aliases it).
import * as THREE from '/node_modules/three/build/three.module.js';
import { buildScene } from './scene.js';

let renderer = null;
let camera = null;
let scene = null;
let needsRender = false;
let frameRequested = false;

function requestRender() {
  needsRender = true;
  if (!frameRequested) {
    frameRequested = true;
    self.requestAnimationFrame(frame);
  }
}

function frame() {
  frameRequested = false;
  if (!needsRender) return;
  needsRender = false;
  renderer.render(scene.root, camera);
}

const handlers = {
  init({ canvas, width, height, pixelRatio }) {
    renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
    renderer.setPixelRatio(pixelRatio);
    renderer.setSize(width, height, false);
    renderer.setClearColor(0x20242b);
    camera = new THREE.PerspectiveCamera(40, width / height, 0.01, 1000);
    scene = buildScene(THREE, camera);
    requestRender();
  },
  resize({ width, height }) {
    renderer.setSize(width, height, false);
    requestRender();
  },
  camera({ position, quaternion, fov, aspect, near, far }) {
    camera.position.fromArray(position);
    camera.quaternion.fromArray(quaternion);
    Object.assign(camera, { fov, aspect, near, far });
    camera.updateProjectionMatrix();
    requestRender();
  },
  model({ snapshot }) { scene.setModel(snapshot); requestRender(); },
  surface({ surface }) { scene.setSurface(surface); requestRender(); },
  visibility({ faces, surface, mirror }) { scene.setVisibility(faces, surface, mirror); requestRender(); },
  mirrorPlane({ plane }) { scene.setMirrorPlane(plane); requestRender(); },
  highlight({ kinds }) { scene.highlightKinds(kinds); requestRender(); },
  buildStep({ state }) { scene.setBuildStep(state); requestRender(); },
  // Reads the pixels in the same task as the draw (no preserveDrawingBuffer needed).
  coverage({ id }) {
    renderer.render(scene.root, camera);
    const gl = renderer.getContext();
    const { width, height } = gl.canvas;
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    self.postMessage({ id, result: { ...scene.colourCoverage(pixels), width, height } });
  },
};

self.onmessage = ({ data }) => {
  try {
    handlers[data.type](data);
  } catch (e) {
    self.postMessage({ id: data.id, error: e.message, type: 'error' });
  }
};
