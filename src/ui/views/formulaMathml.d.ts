/** Served by src/build/formulaMathml.ts: each procedure's equations as MathML, slots marked `slot-<name>`. */
declare module 'virtual:formula-mathml' {
  const mathml: Readonly<Record<import('../../core/procedures/procedures').ProcedureKey, readonly string[]>>;
  export default mathml;
}
