// Download buttons: each asks the worker for the export and saves it. OBJ comes with its MTL, as
// one .zip (two downloads make Chrome ask to allow multiple downloads). GLB is in metres, OBJ in
// millimetres (its header says so); "VEF, no panels" leaves the faces out, so vZome shows balls
// and struts only.
import { exportFileName } from './file_names.js';
import { zipStored } from './zip.js';

export const FORMATS = {
  vef: ['model.vef'], 'vef-struts': ['model-no-panels.vef'], glb: ['model.glb'], obj: ['model.obj', 'model.mtl'],
  json: ['model.zome.json'], csv: ['parts.csv'],
};

// The writers' options of a format (bridge.exportModel), when it has any.
export const OPTIONS = { 'vef-struts': { vefFaces: false } };

// Formats of several files, saved as one zip of this name.
export const ZIPPED = { obj: 'model.zip' };

export function saveBytes(name, bytes) {
  const url = URL.createObjectURL(new Blob([bytes]));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

export class Downloads {
  constructor(root, { bridge, status, baseName }) {
    this.baseName = baseName; // () => name of the current model, e.g. "torus"
    for (const button of root.querySelectorAll('[data-format]')) {
      button.addEventListener('click', async () => {
        try {
          const format = button.dataset.format;
          const files = [];
          for (const file of FORMATS[format]) {
            const name = exportFileName(file, this.baseName());
            files.push({ name, bytes: (await bridge.exportModel(name, OPTIONS[format])).bytes });
          }
          if (ZIPPED[format]) saveBytes(exportFileName(ZIPPED[format], this.baseName()), zipStored(files));
          else for (const f of files) saveBytes(f.name, f.bytes);
        } catch (e) {
          status.error(e.message);
        }
      });
    }
  }
}
