/**
 * The target-Sa box's seam (targetSaPanel.ts, with its worker client): hidden unless a target Sa is
 * asked; its code loads with the first target Sa, not with the first result.
 */
import type { FinishFieldMessage } from '../worker/finishProtocol';
import type { PageReply } from '../worker/pageProtocol';
import { targetSaClient } from '../worker/workers';
import type { FinishInputs } from './finishRequest';
import type { TargetSaPanel } from './targetSaPanel';

/** Stands in for the TargetSaPanel until a target Sa is first asked; then hands it every call. */
export class LazyTargetSa {
  private panel: TargetSaPanel | null = null;
  private loading = false;
  private last: [FinishInputs, PageReply | null, boolean] | null = null;

  constructor(
    private readonly box: HTMLElement | null,
    private readonly onUse: (pair: { readonly L: number; readonly fz: number }) => void,
    private readonly onFieldErrors: (errors: readonly FinishFieldMessage[]) => void,
  ) {}

  /** The inputs on screen, the answer to them (null while none is, or while typing), and whether Sa is the target. */
  show(inputs: FinishInputs, reply: PageReply | null, active: boolean): void {
    this.last = [inputs, reply, active];
    const box = this.box;
    if (this.panel !== null) this.panel.show(inputs, reply, active);
    else if (box !== null && active && !this.loading) {
      this.loading = true;
      void import('./targetSaPanel').then(({ TargetSaPanel }) => {
        this.panel = new TargetSaPanel(box, this.onUse, targetSaClient, this.onFieldErrors);
        if (this.last !== null) this.panel.show(...this.last);
      });
    }
  }
}
