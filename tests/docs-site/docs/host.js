// The host page's listener for a plain iframe (as in the calculator's README): take the height
// the embedded calculator posts, only from that iframe's window and origin.
window.addEventListener('message', (event) => {
  const frame = document.getElementById('plain-frame');
  if (!frame || event.source !== frame.contentWindow) return;
  if (event.origin !== new URL(frame.src, document.baseURI).origin) return;
  const data = event.data;
  if (data && data.type === 'path-interval:resize' && Number.isFinite(data.height)) {
    frame.style.height = `${Math.ceil(data.height)}px`;
  }
});
