// The bundled samples (CC BY meshes, attribution in public/samples/README.md). Each has a
// finished model precomputed at build time (web/build_samples.sh), shown instantly.
export const SAMPLES = [
  { id: 'torus', label: 'Torus', mesh: 'torus.obj', resolution: 8, credit: 'Oded Stein, CC BY 4.0' },
  { id: 'sphere', label: 'Sphere', mesh: 'sphere.obj', resolution: 6, credit: 'Oded Stein, CC BY 4.0' },
  { id: 'cube', label: 'Cube', mesh: 'cube.obj', resolution: 5, credit: 'Oded Stein, CC BY 4.0' },
  { id: 'scorpion', label: 'Scorpion', mesh: 'scorpion.obj', resolution: 12,
    credit: 'YahooJAPAN, remeshed by Oded Stein, CC BY 3.0' },
];
export const DEFAULT_SAMPLE = 'torus';

export function sampleUrl(file) {
  return new URL('samples/' + file, document.baseURI).href;
}

export async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.arrayBuffer();
}
