// Download buttons: each asks the worker for the export and saves it (OBJ comes with its MTL).
import { exportFileName } from './file_names.js';

export const FORMATS = {
  vef: ['model.vef'], glb: ['model.glb'], obj: ['model.obj', 'model.mtl'], json: ['model.zome.json'], csv: ['parts.csv'],
};

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
          for (const file of FORMATS[button.dataset.format]) {
            const name = exportFileName(file, this.baseName());
            const { bytes } = await bridge.exportModel(name);
            saveBytes(name, bytes);
          }
        } catch (e) {
          status.error(e.message);
        }
      });
    }
  }
}
