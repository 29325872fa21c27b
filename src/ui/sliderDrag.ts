/**
 * Mouse and pen drags of the page's sliders, handled by the page so that a new value and its
 * answer appear in the same frame.
 *
 * The browser's own drag delivers a slider's `input` event with the frame (pointer moves are
 * aligned to animation frames), so the worker's answer, back about 2 ms later, can only be drawn
 * one frame after the new value: every step of a drag showed the results marked stale for a
 * frame, and a continuous drag showed them stale throughout. Here the value follows the pointer's
 * raw updates (`pointerrawupdate`, dispatched as soon as the pointer moves; `pointermove` where a
 * browser lacks it), at most one new value per frame and early in it, so the answer is back
 * before the frame is drawn. Touch keeps the browser's own slider (and its scrolling); the
 * keyboard is untouched.
 */

/** Where a slider's thumb travels, in viewport CSS pixels. */
export interface SliderTrack {
  /** Left edge of the slider's box. */
  readonly leftPx: number;
  /** Width of the slider's box. */
  readonly widthPx: number;
  /** The thumb's width (its centre travels from half a thumb inside one end to the other). */
  readonly thumbPx: number;
}

/** A slider's numeric range (its min, max and step attributes). */
export interface SliderSteps {
  readonly min: number;
  readonly max: number;
  readonly step: number;
}

/**
 * The value a slider takes when its thumb is centred under the pointer at `pointerXPx` (viewport
 * CSS px): the position along the thumb's travel, snapped to a whole number of steps from `min`
 * and never past `max` (as a range input aligns values), without float noise. Pure.
 */
export function sliderValueAt(pointerXPx: number, track: SliderTrack, range: SliderSteps): number {
  const travelPx = track.widthPx - track.thumbPx;
  const fraction = travelPx > 0 ? (pointerXPx - track.leftPx - track.thumbPx / 2) / travelPx : 0;
  const span = range.max - range.min;
  if (!(span > 0) || !(range.step > 0)) return range.min;
  const maxSteps = Math.floor(span / range.step + 1e-9);
  const steps = Math.min(maxSteps, Math.max(0, Math.round((Math.min(1, Math.max(0, fraction)) * span) / range.step)));
  return Number((range.min + steps * range.step).toPrecision(12));
}

/** The thumb's width from the stylesheet (`--range-thumb` on the slider), 0 when not given. */
function thumbWidthPx(slider: HTMLInputElement): number {
  return Number.parseFloat(getComputedStyle(slider).getPropertyValue('--range-thumb')) || 0;
}

/** Takes over mouse and pen drags of `slider` (see the file's comment); returns a function that stops it. */
export function dragEarly(slider: HTMLInputElement): () => void {
  const moveEvent = 'onpointerrawupdate' in window ? 'pointerrawupdate' : 'pointermove';
  let pointerId: number | null = null;
  /** A value was set in this frame: later moves wait for the frame to be drawn. */
  let waiting = false;
  let pendingXPx: number | null = null;

  const apply = (xPx: number) => {
    const box = slider.getBoundingClientRect();
    const value = sliderValueAt(
      xPx,
      { leftPx: box.left, widthPx: box.width, thumbPx: thumbWidthPx(slider) },
      { min: Number(slider.min), max: Number(slider.max), step: Number(slider.step) },
    );
    const before = slider.value;
    slider.value = String(value);
    if (slider.value !== before) slider.dispatchEvent(new Event('input', { bubbles: true }));
  };
  const move = (xPx: number) => {
    if (waiting) {
      pendingXPx = xPx;
      return;
    }
    apply(xPx);
    waiting = true;
    // After this frame is drawn, the latest waiting move (if any) starts the next one.
    requestAnimationFrame(() =>
      setTimeout(() => {
        waiting = false;
        const next = pendingXPx;
        pendingXPx = null;
        if (next !== null && pointerId !== null) move(next);
      }, 0),
    );
  };
  const onMove = (event: Event) => {
    const e = event as PointerEvent;
    if (e.pointerId === pointerId) move(e.clientX);
  };
  const onDown = (e: PointerEvent) => {
    if (e.pointerType === 'touch' || e.button !== 0 || slider.disabled || pointerId !== null) return;
    e.preventDefault(); // no native drag (nor the focus it would give: given here)
    slider.focus({ preventScroll: true });
    slider.setPointerCapture(e.pointerId);
    pointerId = e.pointerId;
    slider.addEventListener(moveEvent, onMove);
    move(e.clientX);
  };
  const onUp = (e: PointerEvent) => {
    if (e.pointerId !== pointerId) return;
    pointerId = null;
    slider.removeEventListener(moveEvent, onMove);
    if (pendingXPx !== null) apply(pendingXPx);
    pendingXPx = null;
    slider.dispatchEvent(new Event('change', { bubbles: true }));
  };
  slider.addEventListener('pointerdown', onDown);
  slider.addEventListener('pointerup', onUp);
  slider.addEventListener('pointercancel', onUp);
  return () => {
    slider.removeEventListener('pointerdown', onDown);
    slider.removeEventListener('pointerup', onUp);
    slider.removeEventListener('pointercancel', onUp);
    slider.removeEventListener(moveEvent, onMove);
  };
}
