// File names: the model's base name from what was loaded, and the names its downloads get. Pure,
// so the unit tests (web/tests/) pin them down.

const MODEL_EXTENSION = /\.(zome\.json|json|vef|obj|stl|ply|off|gltf|glb)$/i;

/** A model file (.zome.json, .json, .vef), not a mesh: the core reads it as a finished model. */
export function isModelFileName(fileName) {
  return /\.(zome\.json|json|vef)$/i.test(fileName);
}

/** "torus.zome.json" → "torus", "Bunny.STL" → "Bunny"; "model" when nothing is left. */
export function modelBaseName(fileName) {
  return fileName.replace(MODEL_EXTENSION, '') || 'model';
}

/**
 * A download's name from its template in downloads.js FORMATS: "model.obj" → "<base>.obj",
 * "model-no-panels.vef" → "<base>-no-panels.vef" (two VEF buttons, two names), "parts.csv" →
 * "<base>-parts.csv". Only the template's stem is replaced, once, and the base is taken literally
 * (String.replace would expand `$&` in it, and a second replace would hit a base that itself
 * contains "parts").
 */
export function exportFileName(template, base) {
  const dot = template.indexOf('.');
  const stem = template.slice(0, dot), extension = template.slice(dot);
  const suffix = stem === 'parts' ? '-parts' : stem.startsWith('model-') ? stem.slice(5) : '';
  return base + suffix + extension;
}

/** The last path segment of a URL, decoded; "mesh" when empty. Never throws on a bad %-escape. */
export function fileNameFromUrl(url, baseUrl) {
  let path;
  try {
    path = new URL(url, baseUrl).pathname;
  } catch {
    path = String(url); // not a URL: the fetch will say so, under this name
  }
  const last = path.split('/').pop() || 'mesh';
  try {
    return decodeURIComponent(last);
  } catch {
    return last; // e.g. "50%off.obj": keep it as written rather than reject the load
  }
}
