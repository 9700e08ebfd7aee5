#include "backplot/offscreen.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>
#include <vtkPointData.h>

#include <cstdlib>
#include <cstring>

namespace k528::backplot {

bool renderOffscreen(BackplotScene& scene, int w, int h, const std::string& pngPath,
                     std::vector<unsigned char>* rgb, std::string& error) {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        error = "rendering needs an X server (Debian's VTK is built for X/GLX): run under "
                "xvfb-run -a -s \"-screen 0 1280x800x24\"";
        return false;
    }
    vtkNew<vtkRenderWindow> win;
    win->SetOffScreenRendering(1);
    win->SetMultiSamples(0);
    win->SetSize(w, h);
    win->AddRenderer(scene.renderer());
    scene.fit(w, h);
    win->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(win);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkImageData* img = grab->GetOutput();
    if (rgb) {
        vtkUnsignedCharArray* a =
            vtkUnsignedCharArray::SafeDownCast(img->GetPointData()->GetScalars());
        if (!a || a->GetNumberOfComponents() != 3) {
            error = "the renderer gave no RGB image";
            win->RemoveRenderer(scene.renderer());
            return false;
        }
        rgb->resize(static_cast<std::size_t>(a->GetNumberOfValues()));
        std::memcpy(rgb->data(), a->GetPointer(0), rgb->size());
    }
    if (!pngPath.empty()) {
        vtkNew<vtkPNGWriter> png;
        png->SetFileName(pngPath.c_str());
        png->SetInputConnection(grab->GetOutputPort());
        png->Write();
        if (png->GetErrorCode() != 0) {
            error = "cannot write " + pngPath;
            win->RemoveRenderer(scene.renderer());
            return false;
        }
    }
    win->RemoveRenderer(scene.renderer());
    return true;
}

} // namespace k528::backplot
