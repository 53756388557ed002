/* Preloaded into the explorer's tests in the sanitizer build: dlclose() does nothing, so the
 * modules that Qt and Mesa load and unload (platform plugins, GL drivers) are still mapped when
 * LeakSanitizer reports at exit. Their allocations then carry their library's name, which
 * lsan.supp can name, instead of "<unknown module>", which nothing can. */
int dlclose(void* handle)
{
  (void)handle;
  return 0;
}
