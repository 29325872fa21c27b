/** Served by src/build/sharedWorker.ts: the URL of the solver worker's module script. */
declare module 'virtual:solver-worker-url' {
  const url: string;
  export default url;
}
