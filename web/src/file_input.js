// Input: drag and drop anywhere on the page, and the file picker. Calls onFile(File).
export function setupFileInput({ dropTarget, picker, overlay, onFile }) {
  let depth = 0;
  const show = (on) => overlay.classList.toggle('visible', on);
  dropTarget.addEventListener('dragenter', (e) => { e.preventDefault(); depth++; show(true); });
  dropTarget.addEventListener('dragleave', () => { depth = Math.max(0, depth - 1); if (!depth) show(false); });
  dropTarget.addEventListener('dragover', (e) => e.preventDefault());
  dropTarget.addEventListener('drop', (e) => {
    e.preventDefault();
    depth = 0;
    show(false);
    const file = e.dataTransfer?.files?.[0];
    if (file) onFile(file);
  });
  picker.addEventListener('change', () => {
    const file = picker.files?.[0];
    if (file) onFile(file);
    picker.value = '';
  });
}
