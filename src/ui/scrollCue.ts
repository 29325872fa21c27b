/**
 * A cue on boxes that scroll sideways (a long formula on a phone): the box's frame (its parent, which
 * does not scroll) is marked `data-more-left` / `data-more-right` while content lies hidden on that
 * side, and the stylesheet shades that edge (scrollCue.css). Marks follow scrolling, the box's size
 * and its content's (a formula widens as its font loads); a box whose content fits carries neither,
 * and the shade goes once the box is scrolled to its end. The frame carries the shade, not the
 * scrolling box: Chromium did not repaint a scroller's own inset shadow when it changed.
 */

/** Content hidden on a side by less than this (px) does not count (sub-pixel rounding). */
const SLACK_PX = 1;

/** Which sides of a box scrolled `scrollLeftPx` hide content (px, the box's scroll metrics). */
export function hiddenSides(
  scrollLeftPx: number,
  clientWidthPx: number,
  scrollWidthPx: number,
): { left: boolean; right: boolean } {
  return {
    left: scrollLeftPx > SLACK_PX,
    right: scrollLeftPx + clientWidthPx < scrollWidthPx - SLACK_PX,
  };
}

/** Marks a set of boxes; `clear()` stops watching them all (their owner is about to replace them). */
export class ScrollCues {
  /** Each box watched, by itself and by each of its children (whose sizes are observed too). */
  private readonly boxOf = new Map<Element, HTMLElement>();
  private readonly resize = new ResizeObserver((entries) => {
    for (const e of entries) {
      const box = this.boxOf.get(e.target);
      if (box) this.mark(box);
    }
  });
  private readonly onScroll = (e: Event): void => {
    if (e.currentTarget instanceof HTMLElement) this.mark(e.currentTarget);
  };

  /** Starts watching a box, in its frame (class `scroll-cue-frame` added): the box's content is in place. */
  watch(box: HTMLElement, frame: HTMLElement): void {
    frame.classList.add('scroll-cue-frame');
    box.addEventListener('scroll', this.onScroll, { passive: true });
    for (const target of [box, ...box.children]) {
      this.boxOf.set(target, box);
      this.resize.observe(target);
    }
  }

  /** Stops watching every box. */
  clear(): void {
    for (const [target, box] of this.boxOf) {
      box.removeEventListener('scroll', this.onScroll);
      this.resize.unobserve(target);
    }
    this.boxOf.clear();
  }

  private mark(box: HTMLElement): void {
    const frame = box.parentElement;
    if (frame === null) return;
    const sides = hiddenSides(box.scrollLeft, box.clientWidth, box.scrollWidth);
    frame.toggleAttribute('data-more-left', sides.left);
    frame.toggleAttribute('data-more-right', sides.right);
  }
}
