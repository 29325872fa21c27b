/**
 * The tool shelf's seam (toolShelf.ts: saved tools and imported libraries): its code loads on first
 * use, when the shelf is first opened or a file is first dragged onto it, not with the first result.
 */
import type { LengthUnit } from '../core/input/units';
import type { ToolShelf, ToolShelfEvents } from './toolShelf';

/** Stands in for the ToolShelf until it is used; then builds it in `root` and hands it every call. */
export class LazyToolShelf {
  private shelf: ToolShelf | null = null;
  private loading: Promise<ToolShelf> | null = null;
  private unit: LengthUnit = 'mm';

  constructor(
    private readonly root: HTMLDetailsElement,
    private readonly events: ToolShelfEvents,
  ) {
    root.addEventListener('toggle', () => {
      if (root.open) void this.load();
    });
    // Before it loads, the shelf takes a dropped file all the same (then the shelf's own handlers do).
    root.addEventListener('dragover', (e) => {
      if (this.shelf !== null) return;
      e.preventDefault();
      void this.load();
    });
    root.addEventListener('drop', (e) => {
      if (this.shelf !== null) return;
      e.preventDefault();
      const file = e.dataTransfer?.files[0];
      void this.load().then((shelf) => file && shelf.importFile(file));
    });
  }

  /** The page's unit changed (the lists' labels follow once the shelf is built). */
  render(unit: LengthUnit): void {
    this.unit = unit;
    this.shelf?.render(unit);
  }

  /** The shelf, built on the first call (its module loads then). */
  load(): Promise<ToolShelf> {
    this.loading ??= import('./toolShelf').then(({ ToolShelf }) => {
      const shelf = new ToolShelf(this.root, this.events);
      shelf.render(this.unit);
      this.shelf = shelf;
      return shelf;
    });
    return this.loading;
  }
}
