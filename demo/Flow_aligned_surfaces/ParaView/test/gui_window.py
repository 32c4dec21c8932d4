"""The whole ParaView window from a --script of the GUI, for the tutorial's screenshots.

SaveScreenshot saves a view only, and Debian's ParaView 5.11 is built without PythonQt, so a
script cannot reach the Qt widgets.  Two libraries every ParaView GUI has loaded do it instead,
through ctypes:
- Qt: while a --script runs, the GUI's event loop waits for it, so the pipeline browser and the
  properties panel show nothing of what the script did; QCoreApplication::processEvents() (a
  static function; its QFlags argument is passed as an int) lets Qt lay out and paint them;
- Xlib: the main window is a top-level X window; XMoveResizeWindow gives it a known size (there
  is no window manager under Xvfb) and XGetImage reads what the X server shows, the render
  view's OpenGL picture included.
No tool beyond the GUI's own libraries is needed (no xwd, no ImageMagick)."""
import ctypes
import time

_qt = ctypes.CDLL("libQt5Core.so.5")
_process_events = _qt._ZN16QCoreApplication13processEventsE6QFlagsIN10QEventLoop17ProcessEventsFlagEE
_process_events.argtypes = [ctypes.c_int]
_process_events.restype = None

_x = ctypes.CDLL("libX11.so.6")
_x.XOpenDisplay.restype = ctypes.c_void_p
_x.XOpenDisplay.argtypes = [ctypes.c_char_p]
_x.XDefaultRootWindow.restype = ctypes.c_ulong
_x.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
_x.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                          ctypes.POINTER(ctypes.c_ulong), ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)),
                          ctypes.POINTER(ctypes.c_uint)]
_x.XMoveResizeWindow.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int,
                                 ctypes.c_uint, ctypes.c_uint]
_x.XSync.argtypes = [ctypes.c_void_p, ctypes.c_int]
_x.XFree.argtypes = [ctypes.c_void_p]
_x.XGetImage.restype = ctypes.c_void_p
_x.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint,
                         ctypes.c_uint, ctypes.c_ulong, ctypes.c_int]


class _WindowAttributes(ctypes.Structure):
    _fields_ = [("x", ctypes.c_int), ("y", ctypes.c_int), ("width", ctypes.c_int), ("height", ctypes.c_int),
                ("border_width", ctypes.c_int), ("depth", ctypes.c_int), ("visual", ctypes.c_void_p),
                ("root", ctypes.c_ulong), ("class_", ctypes.c_int), ("bit_gravity", ctypes.c_int),
                ("win_gravity", ctypes.c_int), ("backing_store", ctypes.c_int),
                ("backing_planes", ctypes.c_ulong), ("backing_pixel", ctypes.c_ulong),
                ("save_under", ctypes.c_int), ("colormap", ctypes.c_ulong), ("map_installed", ctypes.c_int),
                ("map_state", ctypes.c_int), ("all_event_masks", ctypes.c_long),
                ("your_event_mask", ctypes.c_long), ("do_not_propagate_mask", ctypes.c_long),
                ("override_redirect", ctypes.c_int), ("screen", ctypes.c_void_p)]


class _Image(ctypes.Structure):  # XImage up to the fields read here
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("xoffset", ctypes.c_int),
                ("format", ctypes.c_int), ("data", ctypes.POINTER(ctypes.c_ubyte)),
                ("byte_order", ctypes.c_int), ("bitmap_unit", ctypes.c_int),
                ("bitmap_bit_order", ctypes.c_int), ("bitmap_pad", ctypes.c_int), ("depth", ctypes.c_int),
                ("bytes_per_line", ctypes.c_int), ("bits_per_pixel", ctypes.c_int),
                ("red_mask", ctypes.c_ulong), ("green_mask", ctypes.c_ulong), ("blue_mask", ctypes.c_ulong),
                ("obdata", ctypes.c_void_p),
                # XDestroyImage is a macro of Xlib.h calling the image's own function (f.destroy_image)
                ("create_image", ctypes.c_void_p),
                ("destroy_image", ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p))]


_x.XGetWindowAttributes.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(_WindowAttributes)]
_ALL_PLANES, _Z_PIXMAP = 0xFFFFFFFF, 2


def process_events(seconds=0.3):
    """Lets the GUI handle its events (layout, painting) for about `seconds`."""
    end = time.time() + seconds
    while True:
        _process_events(0)
        if time.time() >= end:
            return
        time.sleep(0.02)


class Window:
    """ParaView's main window: the largest mapped top-level window of the display."""

    def __init__(self):
        self.display = _x.XOpenDisplay(None)
        if not self.display:
            raise RuntimeError("gui_window: no X display (DISPLAY is not set or not reachable)")
        self.root = _x.XDefaultRootWindow(self.display)

    def _main_window(self):
        root, parent = ctypes.c_ulong(), ctypes.c_ulong()
        children, count = ctypes.POINTER(ctypes.c_ulong)(), ctypes.c_uint()
        _x.XQueryTree(self.display, self.root, ctypes.byref(root), ctypes.byref(parent),
                      ctypes.byref(children), ctypes.byref(count))
        best = None
        for i in range(count.value):
            a = _WindowAttributes()
            _x.XGetWindowAttributes(self.display, children[i], ctypes.byref(a))
            if a.map_state == 2 and (best is None or a.width * a.height > best[1].width * best[1].height):
                best = (children[i], a)
        if children:
            _x.XFree(children)
        if best is None:
            raise RuntimeError("gui_window: no mapped window on the display")
        return best

    def resize(self, width, height):
        window, _ = self._main_window()
        _x.XMoveResizeWindow(self.display, window, 0, 0, width, height)
        _x.XSync(self.display, 0)
        process_events(1.0)

    def grab(self):
        """The main window as a numpy array (height x width x 3, uint8, RGB), after letting the
        GUI paint what the script changed."""
        import numpy
        process_events(0.5)
        _, a = self._main_window()
        pointer = _x.XGetImage(self.display, self.root, a.x, a.y, a.width, a.height, _ALL_PLANES, _Z_PIXMAP)
        if not pointer:
            raise RuntimeError("gui_window: XGetImage failed")
        image = ctypes.cast(pointer, ctypes.POINTER(_Image)).contents
        try:
            if image.bits_per_pixel != 32:
                raise RuntimeError("gui_window: %d bits per pixel (a 24-bit Xvfb screen is expected)" %
                                   image.bits_per_pixel)
            raw = numpy.ctypeslib.as_array(image.data, shape=(image.height * image.bytes_per_line,))
            rows = raw.reshape(image.height, image.bytes_per_line)[:, :4 * image.width]
            pixels = rows.reshape(image.height, image.width, 4)
            return pixels[:, :, [2, 1, 0]].copy()  # BGRX in memory (red_mask 0xff0000, little endian)
        finally:
            image.destroy_image(pointer)

    def save(self, path):
        """Writes the main window as a PNG (VTK's writer) and returns the pixels."""
        from vtkmodules.vtkCommonDataModel import vtkImageData
        from vtkmodules.vtkIOImage import vtkPNGWriter
        from vtkmodules.util.numpy_support import numpy_to_vtk
        pixels = self.grab()
        height, width, _ = pixels.shape
        image = vtkImageData()
        image.SetDimensions(width, height, 1)
        array = numpy_to_vtk(pixels[::-1].reshape(-1, 3).copy(), deep=1)  # VTK's rows run bottom up
        array.SetName("pixels")
        image.GetPointData().SetScalars(array)
        writer = vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputData(image)
        writer.Write()
        return pixels
